#include "comms/openfresco/OpenSeesTwinSite.h"

#include "core/config/JsonCursor.h"
#include "core/config/NumericalSite.h"
#include "core/config/TestConfig.h"

namespace hsmu::comms::of {

void installOpenSeesTwins(OpenSeesTwinOptions options)
{
    setNumericalSiteFactory([options](const ElementSpec& spec, std::unique_ptr<HysteresisLaw> model)
                                -> std::unique_ptr<HysteresisLaw> {
        NumericalSiteAddress a;
        std::string why;
        if (!parseNumericalSite(spec.numericalSite, a, why))
            throw ConfigError(why);
        if (std::string no = OpenSeesTwinLaw::supported(model->lawName()); !no.empty())
            throw ConfigError(no);
        return std::make_unique<OpenSeesTwinLaw>(a.host, a.port, spec.name, std::move(model),
                                                 options);
    });
}

} // namespace hsmu::comms::of
