#include "core/record/SpecimenColumns.h"

#include <stdexcept>

namespace hsmu {

double SpecimenColumns::deformation(const RecordData& r, int row) const
{
    return deformationChannel >= 0 ? r.channels(row, deformationChannel)
                                   : r.deformation(row, element);
}

double SpecimenColumns::force(const RecordData& r, int row) const
{
    return forceChannel >= 0 ? r.channels(row, forceChannel) : r.force(row, element);
}

SpecimenColumns specimenColumns(const RecordData& r, const std::string& element,
                                const std::string& source, std::string basicDof)
{
    const std::string where = source.empty() ? "" : source + ": ";
    SpecimenColumns c;
    const auto& elements = r.layout.elements;
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i].name == element && elements[i].experimental)
            c.element = int(i);
    if (c.element < 0)
        throw std::invalid_argument(where + "no specimen (experimental element) named '" +
                                    element + "' in the record");
    c.units = elements[std::size_t(c.element)].units;
    if (basicDof.empty() && r.layout.updating && r.layout.updating->specimen == element)
        basicDof = r.layout.updating->basicDof;
    if (basicDof.empty())
        return c;
    const auto& channels = r.layout.channels;
    for (std::size_t k = 0; k < channels.size(); ++k) {
        if (channels[k].element != element)
            continue;
        if (channels[k].name == basicDof + " deformation") {
            c.deformationChannel = int(k);
            c.units.deformation = channels[k].unit;
        } else if (channels[k].name == basicDof + " force") {
            c.forceChannel = int(k);
            c.units.force = channels[k].unit;
        }
    }
    if (c.deformationChannel < 0 || c.forceChannel < 0 || r.channels.rows() < r.rows())
        throw std::invalid_argument(where + "no " + basicDof + " deformation and force "
                                    "channels of '" + element + "' in the record");
    return c;
}

} // namespace hsmu
