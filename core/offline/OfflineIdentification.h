#pragma once
// OfflineIdentification: re-run the identification of a specimen after the test, on its
// measured history (a run record or an imported CSV; SpecimenHistory.h), with the recorded
// or overridden settings (IdentificationSettings.h). docs/cli.md, `hsmu replay --identify`.
//
// Each sample goes through the same ModelUpdater as the online run (docs/method.md, The four
// modules: auxiliary model <- measured deformation, identifier <- (deformation, force), inspector
// <- auxiliary vs measured force), the specimen's measurement being played back instead of
// measured. So with the recorded settings the parameter history equals the online one (the
// UKF is deterministic: equal to the last bit on the same machine and build), and the
// Nelder-Mead identifier refits when the inspector asks (fit error above its threshold,
// after its cooldown), as online. With settings.finalFit (Nelder-Mead only) one more fit
// over the whole history follows the last sample.
//
// Outputs per sample k (after it was identified): the estimate and its standard deviations
// (the law's units: normalized by uRef / fRef for Bouc-Wen; 0 where the method has none),
// the auxiliary model's force (the prediction with the estimate known before sample k), and
// the inspector's fit error e = RMS(F_aux - F) / RMS(F) over its sliding window [-].
// Summary: the final estimate and the RMS force error of the final model replayed from the
// virgin state over the whole history (HistoryFit::rmsError) [force units] and its ratio to
// RMS(F) [-]; the same for the initial model, and an alarm (worseThanInitial, also among the
// messages) when the final model is the worse of the two.
// Calibration (settings.calibrate): the law fitted over the whole history by the global-then-
// local least squares of Calibration.h, with the scales and bounds of CalibrationDefaults.h
// unless the model gives uRef / fRef and the updating section bounds; its NRMSE is the best
// the law can do, and above settings.verdictNrmse the verdict says so. settings.online false
// skips the online pass (only the calibration; no per-sample rows).
// Errors: std::invalid_argument for an unusable history (SpecimenHistory::problem()),
// ConfigError for settings the method cannot use. A rejected UKF step is reported, not
// fatal (offline the estimator never holds).
// Cost: one online identification step per sample (UKF: a few us) plus the refits.
// Thread rules: none; independent calls may run on different threads.

#include "core/identification/Calibration.h"
#include "core/identification/ParameterSet.h"
#include "core/offline/IdentificationSettings.h"
#include "core/offline/SpecimenHistory.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsmu {

struct OfflineIdentificationResult {
    std::string method;                      ///< "UKF" or "Nelder-Mead"
    std::vector<std::string> parameterNames; ///< column order of parameters / stddev
    ParameterValues initial;                 ///< the estimate before sample 0
    Eigen::MatrixXd parameters;              ///< [N x nParam] estimate after sample k
    Eigen::MatrixXd stddev;                  ///< [N x nParam]
    Eigen::VectorXd auxiliaryForce;          ///< [N] [force units]
    Eigen::VectorXd fitError;                ///< [N] [-]
    ParameterValues finalEstimate;           ///< after the last sample (and the final fit)
    ParameterValues finalStddev;
    double finalRmsError = 0.0;   ///< replay of the final model over the history [force units]
    double finalNrmse = 0.0;      ///< finalRmsError / RMS(F) [-]
    double initialRmsError = 0.0; ///< the initial model's, likewise [force units]
    double initialNrmse = 0.0;    ///< initialRmsError / RMS(F) [-] (inf: it fails)
    /// "" or the alarm when the final model fits the history worse than the initial one
    std::string worseThanInitial;
    /// The online (auxiliary) model's prediction over the record, each sample with the
    /// estimate known before it: RMS(F_aux - F) / RMS(F) [-] (what the twins were given).
    double auxiliaryNrmse = 0.0;
    int estimatorWarnings = 0;         ///< inspector alarms "estimator rejected" (rejected updates)
    int refits = 0;                    ///< Nelder-Mead fits accepted (the final fit included)
    std::vector<std::string> messages; ///< "t = T s: ..." identifier and inspector messages
    /// The calibration over the whole history (settings.calibrate): the law's optimum.
    std::optional<CalibrationResult> calibration;
    /// "" or "the model family cannot represent this specimen (best NRMSE x.xx)" when the
    /// calibration's NRMSE is above settings.verdictNrmse.
    std::string verdict;
};

/// Where a long identification is (the callback of identifyOffline).
struct OfflineProgress {
    std::size_t samplesDone = 0;  ///< samples identified so far
    std::size_t samples = 0;      ///< of the history
    int refits = 0;               ///< Nelder-Mead fits accepted so far
    int rejected = 0;             ///< rejected identification steps so far
    double elapsedSeconds = 0.0;  ///< wall time since the start [s]
    const char* phase = "online"; ///< "online", "final fit" or "calibration"
    /// The calibration's minimizations (its starts, then its polishes) done and in all, when
    /// the call comes from inside the calibration (else 0 and 0).
    int minimizationsDone = 0, minimizations = 0;
};
using OfflineProgressCallback = std::function<void(const OfflineProgress&)>;

/// Where an identification was when it was cancelled (`hsmu replay` interrupted: its partial
/// summary, docs/cli.md).
struct OfflinePartial {
    std::string method;                      ///< as OfflineIdentificationResult::method
    std::string phase = "online";            ///< "online", "final fit" or "calibration"
    std::size_t samplesDone = 0;             ///< samples identified before the cancel
    std::size_t samples = 0;                 ///< of the history
    int refits = 0;                          ///< Nelder-Mead fits accepted so far
    int rejected = 0;                        ///< rejected identification steps so far
    std::vector<std::string> parameterNames; ///< the method's parameters (empty: none yet)
    ParameterValues estimate; ///< after sample samplesDone - 1 (empty before the online pass
                              ///< reached it, and for a cancelled calibration)
};

/// Thrown by identifyOffline when settings.cancel was set (nothing is returned but where it
/// was: partial()). The online pass checks every 64 samples, the calibration between its
/// iterations.
class OfflineCancelled : public std::runtime_error {
public:
    explicit OfflineCancelled(OfflinePartial partial = {})
        : std::runtime_error("the identification was cancelled"), m_partial(std::move(partial)) {}
    const OfflinePartial& partial() const { return m_partial; }

private:
    OfflinePartial m_partial;
};

/// progress (may be empty) is called on the calling thread every 64 samples of the online
/// pass, before the final fit and the calibration, and after each of the calibration's
/// minimizations (a pinching calibration runs two calibrations: the plain law's, then its own).
OfflineIdentificationResult identifyOffline(const SpecimenHistory& history,
                                            const IdentificationSettings& settings,
                                            const OfflineProgressCallback& progress = {});

} // namespace hsmu
