#include "core/offline/SpecimenHistory.h"

#include "core/record/RecordData.h"

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
    const auto& elements = record.layout.elements;
    int j = -1;
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].name == element && elements[i].experimental)
            j = int(i);
    if (j < 0)
        throw std::invalid_argument(source + ": no specimen (experimental element) named '" +
                                    element + "' in the record");
    SpecimenHistory h;
    h.source = source + " (" + element + ")";
    h.deformationUnits = elements[std::size_t(j)].units.deformation;
    h.forceUnits = elements[std::size_t(j)].units.force;
    for (int r = 1; r < record.rows(); ++r) {
        h.time.push_back(record.time[r]);
        h.deformation.push_back(record.deformation(r, j));
        h.force.push_back(record.force(r, j));
    }
    return h;
}

} // namespace hsmu
