#include "core/config/ConfigUnits.h"

#include "core/config/JsonCursor.h"
#include "core/util/Units.h"

#include <optional>

namespace hsmu {

namespace {

using units::Dimension;

struct Factors {
    double length = 1.0, force = 1.0, rotation = 1.0, moment = 1.0, time = 1.0, mass = 1.0;
    bool identity() const {
        return length == 1.0 && force == 1.0 && rotation == 1.0 && moment == 1.0 &&
               time == 1.0 && mass == 1.0;
    }
};

double unitFactor(const JsonCursor& u, const char* key, Dimension d) {
    const std::string text = u.string(key);
    const auto unit = units::parse(text, d);
    if (!unit)
        u.fail(key, std::string("unknown ") + units::dimensionName(d) + " unit '" + text +
                        "' (expected " + units::accepted(d) + ")");
    return unit->factor;
}

Factors readFactors(const JsonCursor& u) {
    u.requireObject();
    u.allowOnly({"length", "force", "rotation", "moment", "time", "mass"});
    Factors f;
    if (u.has("length"))
        f.length = unitFactor(u, "length", Dimension::Length);
    if (u.has("force"))
        f.force = unitFactor(u, "force", Dimension::Force);
    if (u.has("rotation"))
        f.rotation = unitFactor(u, "rotation", Dimension::Rotation);
    f.moment = u.has("moment") ? unitFactor(u, "moment", Dimension::Moment) : f.force * f.length;
    if (u.has("time"))
        f.time = unitFactor(u, "time", Dimension::Time);
    if (u.has("mass")) {
        const std::string m = u.string("mass");
        if (m == "t")
            f.mass = 1.0;
        else if (m == "kg")
            f.mass = 1e-3;
        else
            u.fail("mass", "unknown mass unit '" + m + "' (expected t, kg)");
    }
    return f;
}

// Multiply obj[key] by factor if it is a number (a wrong type is left for the parser's
// message).
void scale(nlohmann::json& obj, const char* key, double factor) {
    if (obj.is_object() && obj.contains(key) && obj[key].is_number())
        obj[key] = obj[key].get<double>() * factor;
}

void scaleMaterial(nlohmann::json& m, double d, double f, double t) {
    if (!m.is_object() || !m.contains("law") || !m["law"].is_string())
        return;
    std::string law = m["law"].get<std::string>();
    for (char& c : law)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    if (law == "boucwen" || law == "bouc-wen" || law == "boucwenpinching" ||
        law == "bouc-wen-pinching" || law == "mrdamper" || law == "mr-damper") {
        for (const auto& [key, factor] : {std::pair{"uRef", d}, std::pair{"fRef", f}}) {
            if (!m.contains(key))
                m[key] = 1.0;
            scale(m, key, factor);
        }
        if (law == "mrdamper" || law == "mr-damper") { // the dashpots: normalized force x time
            scale(m, "c0", t);
            scale(m, "c1", t);
        }
    } else if (law == "bilinear") {
        scale(m, "k0", f / d);
        scale(m, "fy", f);
    } else if (law == "elastic") {
        scale(m, "k", f / d);
    }
}

void scaleLimits(nlohmann::json& l, double d, double f) {
    scale(l, "deformation", d);
    scale(l, "increment", d);
    scale(l, "force", f);
}

void scaleElement(nlohmann::json& e, const Factors& u) {
    if (!e.is_object())
        return;
    const bool rotational = e.contains("type") && e["type"] == "rotationalBaseSpring";
    const double d = rotational ? u.rotation : u.length;
    const double f = rotational ? u.moment : u.force;
    scale(e, "height", u.length);
    scale(e, "ei", u.force * u.length * u.length);
    if (e.contains("material"))
        scaleMaterial(e["material"], d, f, u.time);
    if (e.contains("limits"))
        scaleLimits(e["limits"], d, f);
    if (e.contains("specimen") && e["specimen"].is_object()) {
        nlohmann::json& s = e["specimen"];
        if (s.contains("material"))
            scaleMaterial(s["material"], d, f, u.time);
        scale(s, "forceNoiseStd", f);
        scale(s, "deformationNoiseStd", d);
        if (s.contains("fracture")) {
            scale(s["fracture"], "atCumulativeDeformation", d);
            scale(s["fracture"], "atTime", u.time);
        }
        if (s.contains("actuator")) {
            scale(s["actuator"], "timeConstant", u.time);
            scale(s["actuator"], "delay", u.time);
        }
        if (s.contains("interlock"))
            scaleLimits(s["interlock"], d, f);
    }
}

} // namespace

nlohmann::json toConsoleUnits(const nlohmann::json& document, const std::string& sourceName) {
    if (!document.is_object() || !document.contains("units"))
        return document;
    const JsonCursor root(document, sourceName);
    const Factors u = readFactors(root.child("units"));
    if (u.identity())
        return document;
    nlohmann::json doc = document;
    if (doc.contains("structure") && doc["structure"].is_object()) {
        nlohmann::json& s = doc["structure"];
        if (s.contains("dofs") && s["dofs"].is_array())
            for (auto& dof : s["dofs"])
                scale(dof, "mass", u.mass);
        if (s.contains("damping")) {
            scale(s["damping"], "a0", 1.0 / u.time);
            scale(s["damping"], "a1", u.time);
        }
        if (s.contains("elements") && s["elements"].is_array())
            for (auto& e : s["elements"])
                scaleElement(e, u);
    }
    if (doc.contains("groundMotion"))
        scale(doc["groundMotion"], "dt", u.time);
    if (doc.contains("analysis")) {
        scale(doc["analysis"], "dt", u.time);
        scale(doc["analysis"], "duration", u.time);
    }
    return doc;
}

} // namespace hsmu
