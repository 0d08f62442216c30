#pragma once
// ActuatorColumns: the writer's part of /elements/actuator (docs/recording.md): per step and
// element the actuator's commanded position, measured position, held ticks and flags, as
// ExperimentalControl::actuatorChannels() reported them (ElementSample::actuator). Four
// [N x nElem] f64 datasets commanded, measured, held_ticks, flags with attribute names (and
// units for the two positions); NaN where a control reports no such channel (numerical
// elements, step 0, OpenFresco's ticks and flags). Private to core/record (HDF5 inside).
// Thread rules: RecordWriter's.

#include "core/experiment/StepRecord.h"
#include "core/record/Hdf5Util.h"

#include <string>
#include <vector>

namespace hsmu {

class ActuatorColumns {
public:
    /// Create the group "actuator" under elementsGroup. Throws RecordError naming `where`.
    void create(hid_t elementsGroup, const std::vector<std::string>& names,
                const std::vector<std::string>& deformationUnits, const std::string& where,
                int deflate = 0);
    /// Buffered rows (RecordWriter fills one batch while its thread writes another).
    struct Rows {
        std::vector<double> cmd, measured, ticks, flags;
        void clear();
        void reserve(std::size_t values);
    };
    /// Buffer one step's row into rows (elements beyond r.elements: NaN).
    void buffer(const StepRecord& r, Rows& rows) const;
    /// Append the `count` rows of `rows` (every buffer holds count x nElem values).
    void write(const Rows& rows, hsize_t count);
    /// Close the datasets (RecordWriter::finish).
    void close();

private:
    std::size_t m_nElem = 0;
    h5::Extendible m_cmd, m_measured, m_ticks, m_flags;
};

} // namespace hsmu
