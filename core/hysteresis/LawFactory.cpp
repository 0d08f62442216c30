#include "core/hysteresis/LawFactory.h"

#include "core/hysteresis/Bilinear.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/hysteresis/MrDamper.h"
#include "core/hysteresis/OffsetLaw.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace hsmu {

namespace {

// One named parameter of a law's parameter struct P, with its single-value admissibility.
template <typename P> struct ParameterSpec {
    const char* name;
    double P::*field;
    bool (*ok)(double);
    const char* expected;
};

bool anyFinite(double v) {
    return std::isfinite(v);
}
bool positive(double v) {
    return std::isfinite(v) && v > 0.0;
}
bool nonNegative(double v) {
    return std::isfinite(v) && v >= 0.0;
}
bool unitInterval(double v) {
    return std::isfinite(v) && v >= 0.0 && v <= 1.0;
}
bool belowOne(double v) {
    return std::isfinite(v) && v >= 0.0 && v < 1.0;
}

const ParameterSpec<BoucWenParameters> kBoucWenSpecs[] = {
    {"k0", &BoucWenParameters::k0, positive, "a finite number > 0"},
    {"alpha", &BoucWenParameters::alpha, unitInterval, "a number in [0, 1]"},
    {"n", &BoucWenParameters::n, positive, "a finite number > 0"},
    {"beta", &BoucWenParameters::beta, anyFinite, "a finite number"},
    {"gamma", &BoucWenParameters::gamma, anyFinite, "a finite number"},
    {"A0", &BoucWenParameters::A0, positive, "a finite number > 0"},
    {"deltaA", &BoucWenParameters::deltaA, nonNegative, "a finite number >= 0"},
    {"deltaNu", &BoucWenParameters::deltaNu, nonNegative, "a finite number >= 0"},
    {"deltaEta", &BoucWenParameters::deltaEta, nonNegative, "a finite number >= 0"},
    {"uRef", &BoucWenParameters::uRef, positive, "a finite number > 0"},
    {"fRef", &BoucWenParameters::fRef, positive, "a finite number > 0"},
};

const ParameterSpec<PinchingParameters> kPinchingSpecs[] = {
    {"zetaS", &PinchingParameters::zetaS, belowOne, "a number with 0 <= zetaS < 1"},
    {"p", &PinchingParameters::p, nonNegative, "a finite number >= 0"},
    {"q", &PinchingParameters::q, belowOne, "a number with 0 <= q < 1"},
    {"psi", &PinchingParameters::psi, positive, "a finite number > 0"},
    {"deltaPsi", &PinchingParameters::deltaPsi, nonNegative, "a finite number >= 0"},
    {"lambda", &PinchingParameters::lambda, positive, "a finite number > 0"},
};

const ParameterSpec<MrDamperParameters> kMrDamperSpecs[] = {
    {"c0", &MrDamperParameters::c0, nonNegative, "a finite number >= 0"},
    {"c1", &MrDamperParameters::c1, positive, "a finite number > 0"},
    {"k0", &MrDamperParameters::k0, nonNegative, "a finite number >= 0"},
    {"k1", &MrDamperParameters::k1, nonNegative, "a finite number >= 0"},
    {"f0", &MrDamperParameters::f0, anyFinite, "a finite number"},
    {"alpha", &MrDamperParameters::alpha, nonNegative, "a finite number >= 0"},
    {"A", &MrDamperParameters::A, positive, "a finite number > 0"},
    {"beta", &MrDamperParameters::beta, anyFinite, "a finite number"},
    {"gamma", &MrDamperParameters::gamma, anyFinite, "a finite number"},
    {"n", &MrDamperParameters::n, positive, "a finite number > 0"},
    {"uRef", &MrDamperParameters::uRef, positive, "a finite number > 0"},
    {"fRef", &MrDamperParameters::fRef, positive, "a finite number > 0"},
};

const ParameterSpec<BilinearParameters> kBilinearSpecs[] = {
    {"k0", &BilinearParameters::k0, positive, "a finite number > 0"},
    {"fy", &BilinearParameters::fy, positive, "a finite number > 0"},
    {"b", &BilinearParameters::b, belowOne, "a number with 0 <= b < 1"},
};

struct ElasticParameters {
    double k = 1.0;
};
const ParameterSpec<ElasticParameters> kElasticSpecs[] = {
    {"k", &ElasticParameters::k, positive, "a finite number > 0"},
};

std::string formatValue(double v) {
    char buffer[40];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

template <typename P, std::size_t N> std::string nameList(const ParameterSpec<P> (&specs)[N]) {
    std::string list;
    for (const auto& s : specs) {
        list += list.empty() ? s.name : std::string(", ") + s.name;
    }
    return list;
}

// Fills P from the params named in specs; a name not in specs is an error naming
// `expectedNames` (all of the law's names), unless `others` (the law's other names) has it.
template <typename P, std::size_t N>
P fillParameters(const std::string& law, const ParameterSpec<P> (&specs)[N],
                 const std::map<std::string, double>& params,
                 const std::vector<std::string>& others = {},
                 const std::string& expectedNames = {}) {
    P p{};
    for (const auto& [name, value] : params) {
        const auto* spec = std::find_if(std::begin(specs), std::end(specs),
                                        [&](const auto& s) { return name == s.name; });
        if (spec == std::end(specs)) {
            if (std::find(others.begin(), others.end(), name) != others.end()) {
                continue;
            }
            throw std::invalid_argument(
                law + ": unknown parameter '" + name + "' (expected one of " +
                (expectedNames.empty() ? nameList(specs) : expectedNames) + ")");
        }
        if (!spec->ok(value)) {
            throw std::invalid_argument(law + ": parameter '" + name + "' = " + formatValue(value) +
                                        " is not admissible (expected " + spec->expected + ")");
        }
        p.*(spec->field) = value;
    }
    return p;
}

std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

template <typename P> void requireBoundedZ(const std::string& law, const P& p) {
    if (!(p.beta + p.gamma > 0.0)) {
        throw std::invalid_argument(law + ": parameters 'beta' + 'gamma' = " +
                                    formatValue(p.beta + p.gamma) +
                                    " is not admissible (expected beta + gamma > 0 for a bounded z)");
    }
}

template <typename P, std::size_t N> std::vector<std::string> namesOf(const ParameterSpec<P> (&specs)[N]) {
    std::vector<std::string> names;
    for (const auto& s : specs) {
        names.emplace_back(s.name);
    }
    return names;
}

} // namespace

namespace {

std::unique_ptr<HysteresisLaw> makeInnerLaw(const std::string& lawName,
                                            const std::map<std::string, double>& params) {
    const std::string key = lowerCase(lawName);
    if (key == "boucwen" || key == "bouc-wen") {
        const auto p = fillParameters("boucWen", kBoucWenSpecs, params);
        requireBoundedZ("boucWen", p);
        return std::make_unique<BoucWen>(p);
    }
    if (key == "boucwenpinching" || key == "bouc-wen-pinching") {
        const std::string law = "boucWenPinching";
        const std::string all = nameList(kBoucWenSpecs) + ", " + nameList(kPinchingSpecs);
        BoucWenPinchingParameters p;
        p.boucWen = fillParameters(law, kBoucWenSpecs, params, namesOf(kPinchingSpecs), all);
        p.pinching = fillParameters(law, kPinchingSpecs, params, namesOf(kBoucWenSpecs), all);
        requireBoundedZ(law, p.boucWen);
        return std::make_unique<BoucWenPinching>(p);
    }
    if (key == "mrdamper" || key == "mr-damper") {
        const auto p = fillParameters("mrDamper", kMrDamperSpecs, params);
        requireBoundedZ("mrDamper", p);
        return std::make_unique<MrDamper>(p);
    }
    if (key == "bilinear") {
        return std::make_unique<Bilinear>(fillParameters("bilinear", kBilinearSpecs, params));
    }
    if (key == "elastic") {
        return std::make_unique<LinearElastic>(fillParameters("elastic", kElasticSpecs, params).k);
    }
    throw std::invalid_argument("unknown hysteresis law '" + lawName +
                                "' (expected one of boucWen, bouc-wen, boucWenPinching, "
                                "bouc-wen-pinching, mrDamper, mr-damper, bilinear, elastic)");
}

} // namespace

std::unique_ptr<HysteresisLaw> makeLaw(const std::string& lawName,
                                       const std::map<std::string, double>& params) {
    const auto u0 = params.find(OffsetLaw::kDeformationOffset);
    const auto f0 = params.find(OffsetLaw::kForceOffset);
    if (u0 == params.end() && f0 == params.end())
        return makeInnerLaw(lawName, params);
    std::map<std::string, double> inner = params;
    inner.erase(OffsetLaw::kDeformationOffset);
    inner.erase(OffsetLaw::kForceOffset);
    std::unique_ptr<HysteresisLaw> law = makeInnerLaw(lawName, inner);
    for (const auto& it : {u0, f0})
        if (it != params.end() && !std::isfinite(it->second))
            throw std::invalid_argument(law->lawName() + ": parameter '" + it->first + "' = " +
                                        formatValue(it->second) +
                                        " is not admissible (expected a finite number)");
    return std::make_unique<OffsetLaw>(std::move(law), u0 != params.end() ? u0->second : 0.0,
                                       f0 != params.end() ? f0->second : 0.0);
}

std::vector<std::string> knownLaws() {
    return {"boucWen", "boucWenPinching", "mrDamper", "bilinear", "elastic"};
}

} // namespace hsmu
