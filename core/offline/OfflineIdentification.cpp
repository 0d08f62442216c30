#include "core/offline/OfflineIdentification.h"

#include "core/config/TestFactory.h"
#include "core/config/UpdatingConfig.h"
#include "core/experimental/ExperimentalControl.h"
#include "core/experimental/ExperimentalElement.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryFit.h"
#include "core/structure/Structure.h"
#include "core/updating/Identifier.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/NelderMeadIdentifier.h"

#include <chrono>
#include <functional>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsmu {

namespace {

/// Plays back a measured history: the measurement of step k is sample k, whatever the target.
class PlaybackControl final : public ExperimentalControl {
public:
    explicit PlaybackControl(const SpecimenHistory& h) : m_h(h) {}
    void select(std::size_t k) { m_k = k; }
    std::string description() const override { return "playback of " + m_h.source; }
    ControlResult prepare(double) override { return ControlResult::success(); }
    ControlResult setTarget(double) override { return ControlResult::success(); }
    ControlResult measure(ControlMeasurement& out) override {
        out = {m_h.deformation[m_k], m_h.force[m_k]};
        return ControlResult::success();
    }
    ControlResult commit() override { return ControlResult::success(); }
    void hold(const std::string&) override {}
    void resume() override {}

private:
    const SpecimenHistory& m_h;
    std::size_t m_k = 0;
};

std::string at(double time, const std::string& message) {
    std::ostringstream s;
    s << "t = " << time << " s: " << message;
    return s.str();
}

void putRow(Eigen::MatrixXd& m, Eigen::Index row, const std::vector<double>& values) {
    for (std::size_t j = 0; j < values.size(); ++j)
        m(row, Eigen::Index(j)) = values[j];
}

ParameterValues rowValues(const std::vector<std::string>& names, const Eigen::MatrixXd& m,
                          Eigen::Index row) {
    ParameterValues v;
    for (std::size_t j = 0; j < names.size(); ++j)
        v[names[j]] = m(row, Eigen::Index(j));
    return v;
}

double nrmseOf(const std::string& law, const std::map<std::string, double>& values,
               const SpecimenHistory& h, double& rms) {
    rms = HistoryFit::rmsError(law, values, h.deformation, h.force, 0, h.time);
    double sumF2 = 0.0;
    for (double f : h.force)
        sumF2 += f * f;
    const double rmsF = std::sqrt(sumF2 / double(h.size()));
    return rmsF > 0.0 ? rms / rmsF : 0.0;
}

} // namespace

/// The calibration over the whole history, and the verdict.
void calibrateWhole(const SpecimenHistory& h, const IdentificationSettings& s,
                    OfflineIdentificationResult& r,
                    const std::function<void(int done, int total)>& progress) {
    CalibrationRequest request;
    request.progress = progress;
    request.law = s.model.law;
    request.offsets = s.offsets;
    request.uRef = s.updating.modelURef;
    request.fRef = s.updating.modelFRef;
    request.cancel = s.cancel;
    request.time = h.time; // a rate-dependent law's velocities
    if (s.updating.method == "ukf" && s.updating.ukfFormulation == "robust")
        request.bounds = s.updating.bounds; // the paper's bounds are for its normalization
    try {
        r.calibration = calibrateHistory(h.deformation, h.force, request);
    } catch (const std::exception& e) {
        r.messages.push_back(at(h.time.back(), std::string("calibration: ") + e.what()));
        return;
    }
    if (r.calibration->cancelled)
        throw OfflineCancelled();
    if (!r.calibration->ok) {
        r.messages.push_back(at(h.time.back(), "calibration failed: " + r.calibration->reason));
        return;
    }
    if (r.calibration->nrmse > s.verdictNrmse) {
        std::ostringstream m;
        m.setf(std::ios::fixed);
        m.precision(2);
        m << "the model family cannot represent this specimen (best NRMSE " << r.calibration->nrmse
          << ")";
        r.verdict = m.str();
    }
}

OfflineIdentificationResult identifyOffline(const SpecimenHistory& history,
                                            const IdentificationSettings& settings,
                                            const OfflineProgressCallback& progress) {
    if (const std::string why = history.problem(); !why.empty())
        throw std::invalid_argument(history.source + ": " + why);
    const auto started = std::chrono::steady_clock::now();
    OfflinePartial partial; // where a cancel finds the work (its estimate set by the pass)
    partial.samples = history.size();
    partial.method = "calibration"; // until the online pass names its method
    const auto notify = [&](const char* phase, int minimized, int minimizations) {
        if (!progress)
            return;
        OfflineProgress p;
        p.samplesDone = partial.samplesDone;
        p.samples = history.size();
        p.refits = partial.refits;
        p.rejected = partial.rejected;
        p.phase = phase;
        p.minimizationsDone = minimized;
        p.minimizations = minimizations;
        p.elapsedSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        progress(p);
    };
    const auto tell = [&](std::size_t done, int refits, int rejected, const char* phase) {
        partial.samplesDone = done;
        partial.refits = refits;
        partial.rejected = rejected;
        partial.phase = phase;
        if (settings.cancel && settings.cancel->load())
            throw OfflineCancelled(partial);
        notify(phase, 0, 0);
    };
    const auto calibrateWholeOrCancel = [&](OfflineIdentificationResult& r) {
        try {
            calibrateWhole(history, settings, r, [&](int done, int total) {
                notify("calibration", done, total); // the calibration checks the cancel itself
            });
        } catch (const OfflineCancelled&) {
            throw OfflineCancelled(partial); // with what the pass before it reached
        }
    };
    if (!settings.online) {
        OfflineIdentificationResult r;
        r.method = "calibration";
        tell(0, 0, 0, "calibration");
        calibrateWholeOrCancel(r);
        if (!r.calibration || !r.calibration->ok)
            throw std::invalid_argument("calibration of " + history.source + " failed: " +
                                        (r.messages.empty() ? "" : r.messages.back()));
        r.parameterNames = r.calibration->names;
        for (std::size_t j = 0; j < r.parameterNames.size(); ++j) {
            const double sd = r.calibration->standardDeviation[Eigen::Index(j)];
            r.finalEstimate[r.parameterNames[j]] = r.calibration->estimate[Eigen::Index(j)];
            r.finalStddev[r.parameterNames[j]] = std::isfinite(sd) ? sd : 0.0;
            r.initial[r.parameterNames[j]] = r.calibration->estimate[Eigen::Index(j)];
        }
        r.finalNrmse = r.calibration->nrmse;
        r.finalRmsError = r.calibration->rmsError;
        return r;
    }
    const std::string where = "identification of " + history.source;
    auto model = buildLaw(settings.model, where);
    model->setTimeIncrement(settings.dt); // a rate-dependent model: the identifier's copies too
    std::map<std::string, double> all; // every parameter of the law (for the replays)
    const std::vector<std::string> lawNames = model->parameterNames();
    for (std::size_t i = 0; i < lawNames.size(); ++i)
        all[lawNames[i]] = model->parameterValue(static_cast<int>(i));
    const std::map<std::string, double> initialValues = all;
    auto identifier = buildIdentifier(settings.updating, *model, settings.dt, where);
    const Identifier& id = *identifier;
    auto* nelderMead = dynamic_cast<NelderMeadIdentifier*>(identifier.get());
    ModelUpdater updater(
        settings.specimen, std::move(model), std::move(identifier), settings.updating.inspector,
        std::make_unique<Reporter>(std::vector<ReporterTarget>{}, ReporterPolicy::EveryStep));
    updater.setMaxConsecutiveRejections(history.size() + 1); // offline: never hold

    Structure structure;
    structure.addDof("playback", 1.0);
    auto control = std::make_unique<PlaybackControl>(history);
    PlaybackControl& playback = *control;
    structure.addElement(std::make_unique<ExperimentalElement>(
        settings.specimen, "playback", std::vector<DofTerm>{{0, 1.0}}, std::move(control),
        SafetyLimits{}, 1.0));
    auto* specimen = static_cast<ExperimentalElement*>(structure.element(settings.specimen));
    std::string error;
    if (!updater.attach(structure, settings.dt, &error))
        throw std::invalid_argument(where + ": " + error);

    OfflineIdentificationResult r;
    r.method = id.methodName();
    r.parameterNames = id.layout().names();
    partial.parameterNames = r.parameterNames;
    partial.method = r.method;
    for (std::size_t j = 0; j < r.parameterNames.size(); ++j)
        r.initial[r.parameterNames[j]] = id.estimate()[j];
    const Eigen::Index n = history.size(), p = Eigen::Index(r.parameterNames.size());
    r.parameters.resize(n, p);
    r.stddev.resize(n, p);
    r.auxiliaryForce.resize(n);
    r.fitError.resize(n);
    std::vector<Alarm> alarms;
    UpdatingSample sample;
    Eigen::VectorXd u(1);
    for (Eigen::Index k = 0; k < n; ++k) {
        playback.select(std::size_t(k));
        u[0] = history.deformation[std::size_t(k)];
        const double t = history.time[std::size_t(k)];
        if (ElementStatus st = specimen->setTrial(u); !st.ok || !(st = specimen->commit()).ok)
            throw std::invalid_argument(where + ": " + st.message); // playback never fails
        const std::size_t before = alarms.size();
        updater.afterCommit(int(k) + 1, t, structure, alarms, sample);
        for (std::size_t a = before; a < alarms.size(); ++a) {
            if (alarms[a].kind == AlarmKind::EstimatorRejected)
                ++r.estimatorWarnings;
            r.messages.push_back(at(t, alarms[a].message));
        }
        putRow(r.parameters, k, sample.parameters);
        putRow(r.stddev, k, sample.stddev);
        r.auxiliaryForce[k] = sample.auxiliaryForce;
        r.fitError[k] = sample.fitError;
        const bool refitting = settings.updating.method == "nelderMead";
        if (refitting && k > 0 && r.parameters.row(k) != r.parameters.row(k - 1))
            ++r.refits; // a Nelder-Mead estimate changes only by an accepted fit
        if ((k + 1) % 64 == 0) {
            partial.estimate = rowValues(r.parameterNames, r.parameters, k);
            tell(std::size_t(k) + 1, r.refits, r.estimatorWarnings, "online");
        }
    }
    r.finalEstimate = rowValues(r.parameterNames, r.parameters, n - 1);
    partial.estimate = r.finalEstimate;
    r.finalStddev = rowValues(r.parameterNames, r.stddev, n - 1);
    for (const auto& [name, v] : r.finalEstimate)
        all[name] = v;
    if (settings.finalFit && nelderMead) {
        // One more fit over the whole history, from the last estimate, through the
        // identifier's own scales and box (NelderMeadIdentifier::finalFit).
        tell(history.size(), r.refits, r.estimatorWarnings, "final fit");
        const IdentificationStatus st = nelderMead->finalFit();
        if (!st.message.empty())
            r.messages.push_back(at(history.time.back(), st.message));
        if (!st.ok)
            ++r.estimatorWarnings;
        if (st.updated) {
            ++r.refits;
            for (std::size_t j = 0; j < r.parameterNames.size(); ++j)
                r.finalEstimate[r.parameterNames[j]] = nelderMead->estimate()[j];
            for (const auto& [name, v] : nelderMead->values())
                all[name] = v;
        }
    }
    r.finalNrmse = nrmseOf(settings.model.law, all, history, r.finalRmsError);
    {
        double sumR2 = 0.0, sumF2 = 0.0;
        for (Eigen::Index k = 0; k < n; ++k) {
            const double f = history.force[std::size_t(k)];
            sumR2 += (r.auxiliaryForce[k] - f) * (r.auxiliaryForce[k] - f);
            sumF2 += f * f;
        }
        r.auxiliaryNrmse = sumF2 > 0.0 ? std::sqrt(sumR2 / sumF2) : 0.0;
    }
    // The final model against the initial one: never worse without saying so.
    r.initialNrmse = nrmseOf(settings.model.law, initialValues, history, r.initialRmsError);
    if (std::isfinite(r.initialNrmse) && !(r.finalNrmse <= r.initialNrmse)) {
        std::ostringstream m;
        m << "the final model fits the history worse than the initial one (NRMSE " << r.finalNrmse
          << " against " << r.initialNrmse << ")";
        r.worseThanInitial = m.str();
        r.messages.push_back(at(history.time.back(), r.worseThanInitial));
    }
    if (settings.calibrate) {
        tell(history.size(), r.refits, r.estimatorWarnings, "calibration");
        calibrateWholeOrCancel(r);
    }
    return r;
}

} // namespace hsmu
