#pragma once
// ActuatorColumns: the writer's part of /elements/actuator (docs/recording.md): per step and
// element the actuator's commanded position, measured position, held ticks and flags, as
// ExperimentalControl::actuatorChannels() reported them (ElementSample::actuator). Four
// [N x nElem] f64 datasets commanded, measured, held_ticks, flags with attribute names (and
// units for the two positions); NaN where a control reports no such channel (numerical
// elements, step 0, OpenFresco's ticks and flags). Private to core/record (HDF5 inside).
// Thread rules: RecordWriter's.

#include "core/record/Hdf5Util.h"
#include "core/experiment/StepRecord.h"

#include <string>
#include <vector>

namespace hsmu {

class ActuatorColumns {
public:
    /// Create the group "actuator" under elementsGroup. Throws RecordError naming `where`.
    void create(hid_t elementsGroup, const std::vector<std::string>& names,
                const std::vector<std::string>& deformationUnits, const std::string& where);
    /// Buffer one step's row (elements beyond r.elements: NaN).
    void buffer(const StepRecord& r);
    /// Append the `rows` buffered rows (every buffer holds rows x nElem values).
    void write(hsize_t rows);
    void clear();
    /// Close the datasets (RecordWriter::finish).
    void close();

private:
    std::size_t m_nElem = 0;
    h5::Extendible m_cmd, m_measured, m_ticks, m_flags;
    std::vector<double> m_bCmd, m_bMeasured, m_bTicks, m_bFlags;
};

} // namespace hsmu
