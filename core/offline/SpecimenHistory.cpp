#include "core/offline/SpecimenHistory.h"

#include "core/record/SpecimenColumns.h"

#include <cmath>
#include <stdexcept>

namespace hsmu {

double SpecimenHistory::meanStep() const {
    return time.size() < 2 ? 0.0 : (time.back() - time.front()) / double(time.size() - 1);
}

std::string SpecimenHistory::problem() const {
    if (time.empty())
        return "no samples";
    if (deformation.size() != time.size() || force.size() != time.size())
        return "time, deformation and force have different lengths";
    for (std::size_t k = 0; k < time.size(); ++k) {
        if (!std::isfinite(time[k]) || !std::isfinite(deformation[k]) || !std::isfinite(force[k]))
            return "sample " + std::to_string(k) + " is not finite";
        if (k > 0 && !(time[k] > time[k - 1]))
            return "time does not increase at sample " + std::to_string(k);
    }
    return {};
}

SpecimenHistory historyFromRecord(const RecordData& record, const std::string& element,
                                  const std::string& source) {
    const SpecimenColumns c = specimenColumns(record, element, source);
    SpecimenHistory h;
    h.source = source + " (" + element + ")";
    h.deformationUnits = c.units.deformation;
    h.forceUnits = c.units.force;
    for (int r = 1; r < record.rows(); ++r) {
        h.time.push_back(record.time[r]);
        h.deformation.push_back(c.deformation(record, r));
        h.force.push_back(c.force(record, r));
    }
    return h;
}

} // namespace hsmu
