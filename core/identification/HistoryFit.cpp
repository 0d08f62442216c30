#include "core/identification/HistoryFit.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>

namespace hsmu {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// J (see the header) for a law at its virgin state.
double replayRms(HysteresisLaw& law, const std::vector<double>& u, const std::vector<double>& f,
                 std::size_t window, const std::vector<double>& time) {
    const std::size_t n = u.size();
    const std::size_t first = window == 0 || window >= n ? 0 : n - window;
    const bool rate = law.isRateDependent();
    if (rate && time.size() != n) {
        return kInf;
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        if (rate) {
            law.setTimeIncrement(historyTimeIncrement(time, k));
        }
        if (law.setTrialDeformation(u[k]) != LawStatus::Ok) {
            return kInf;
        }
        law.commit();
        if (k >= first) {
            const double e = law.committedForce() - f[k];
            sum += e * e;
        }
    }
    const double rms = std::sqrt(sum / static_cast<double>(n - first));
    return std::isfinite(rms) ? rms : kInf;
}

std::unique_ptr<HysteresisLaw>
build(const std::string& law, const std::map<std::string, double>& parameters, std::string* error) {
    try {
        return makeLaw(law, parameters);
    } catch (const std::exception& e) {
        if (error != nullptr) {
            *error = e.what();
        }
        return nullptr;
    }
}

} // namespace

double HistoryFit::rmsError(const std::string& law, const std::map<std::string, double>& parameters,
                            const std::vector<double>& deformation,
                            const std::vector<double>& force, std::size_t window,
                            const std::vector<double>& time) {
    if (deformation.empty() || deformation.size() != force.size()) {
        return kInf;
    }
    const auto model = build(law, parameters, nullptr);
    return model ? replayRms(*model, deformation, force, window, time) : kInf;
}

HistoryFitResult HistoryFit::fit(const std::vector<double>& deformation,
                                 const std::vector<double>& force) const {
    const auto start = std::chrono::steady_clock::now();
    HistoryFitResult result;
    const auto elapsed = [&]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const auto fail = [&](std::string reason) {
        result.ok = false;
        result.reason = std::move(reason);
        result.computeSeconds = elapsed();
        return result;
    };

    if (deformation.empty() || deformation.size() != force.size()) {
        return fail("the history needs equally many deformations and forces (at least one)");
    }
    const auto finite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    if (!finite(deformation) || !finite(force)) {
        return fail("the history contains a non-finite value");
    }
    std::string error;
    const std::unique_ptr<HysteresisLaw> prototype = build(m_spec.law, m_spec.initial, &error);
    if (!prototype) {
        return fail(error);
    }
    if (m_spec.fitted.empty()) {
        return fail("no parameter to fit");
    }
    if (prototype->isRateDependent() && m_spec.time.size() != deformation.size()) {
        return fail(m_spec.law + " is rate-dependent: the fit needs the samples' times");
    }
    const auto n = static_cast<Eigen::Index>(m_spec.fitted.size());
    Eigen::VectorXd x0(n), lower(n), upper(n);
    std::vector<int> indices; // the fitted parameters' positions in the law
    for (Eigen::Index i = 0; i < n; ++i) {
        const HistoryFitSpec::Fitted& p = m_spec.fitted[static_cast<std::size_t>(i)];
        indices.push_back(prototype->parameterIndex(p.name));
        if (indices.back() < 0) {
            return fail(m_spec.law + ": unknown parameter '" + p.name + "'");
        }
        const std::optional<double> value = prototype->parameterValue(indices.back());
        if (std::isnan(p.lower) || std::isnan(p.upper) || p.lower > p.upper) {
            return fail(p.name + ": the bounds need lower <= upper");
        }
        if (*value < p.lower || *value > p.upper) {
            return fail(p.name + ": the initial value is outside its bounds");
        }
        x0(i) = *value;
        lower(i) = p.lower;
        upper(i) = p.upper;
    }

    std::unique_ptr<HysteresisLaw> law = prototype->clone();
    const auto objective = [&](const Eigen::VectorXd& x) {
        // Value by value (each judged on those before it), as the fit always has.
        if (law->setParameterValues(indices, std::span<const double>(x.data(), std::size_t(n)),
                                    false) != -1) {
            return kInf; // not admissible for the law
        }
        law->revertToStart();
        return replayRms(*law, deformation, force, m_spec.window, m_spec.time);
    };
    result.rmsBefore = objective(x0);

    const NelderMeadResult nm = NelderMead(m_spec.optimizer).minimize(objective, x0, lower, upper);
    result.evaluations = nm.evaluations + 1;
    result.stop = nm.stop;
    if (nm.stop == NelderMeadStop::InvalidInput) {
        return fail("optimizer: " + nm.reason);
    }
    const bool improved = nm.f < result.rmsBefore;
    const Eigen::VectorXd& xBest = improved ? nm.x : x0;
    const std::vector<std::string> names = prototype->parameterNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
        result.parameters[names[i]] = prototype->parameterValue(static_cast<int>(i));
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        result.parameters[m_spec.fitted[static_cast<std::size_t>(i)].name] = xBest(i);
    }
    result.rmsAfter = improved ? nm.f : result.rmsBefore;
    result.ok = std::isfinite(result.rmsAfter);
    result.reason = result.ok ? nm.reason : "no parameters in the bounds replay the history";
    result.computeSeconds = elapsed();
    return result;
}

} // namespace hsmu
