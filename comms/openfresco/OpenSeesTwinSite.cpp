#include "comms/openfresco/OpenSeesTwinSite.h"

#include "core/config/JsonCursor.h"
#include "core/config/NumericalSite.h"
#include "core/config/TestConfig.h"
#include "core/hysteresis/OffsetLaw.h"

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
        // A model with offsets (OffsetLaw.h): OpenSees runs the law without them and the
        // console adds them around its force, F = F_OpenSees(u - u0) + F0, exactly (the
        // helper's material has no offsets to send them to).
        if (const auto* offsets = dynamic_cast<const OffsetLaw*>(model.get()))
            return std::make_unique<OffsetLaw>(
                std::make_unique<OpenSeesTwinLaw>(a.host, a.port, spec.name,
                                                  offsets->inner().clone(), options),
                offsets->deformationOffset(), offsets->forceOffset());
        return std::make_unique<OpenSeesTwinLaw>(a.host, a.port, spec.name, std::move(model),
                                                 options);
    });
}

} // namespace hsmu::comms::of
