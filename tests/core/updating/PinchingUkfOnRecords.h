#pragma once
// The pinching UKF on a shared record (tests of core/updating): the record reader and the check
// that TestPinchingUkf and TestPinchingUkfHdrb share. QSKIP where ../shared/data is absent.

#include "core/config/JsonCursor.h"
#include "core/offline/OfflineIdentification.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace hsmu::test {

/// A shared hysteresis record "a u f" per line (comments '#'), sampled at 0.01 s.
inline bool readRecord(const std::string& path, SpecimenHistory& h) {
    std::ifstream in(path);
    std::string line;
    double t = 0.0;
    while (in && std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream s(line);
        double a, u, f;
        if (!(s >> a >> u >> f))
            return false;
        h.time.push_back(t);
        t += 0.01;
        h.deformation.push_back(u);
        h.force.push_back(f);
    }
    h.source = path;
    return h.size() > 0;
}

inline int count(const std::vector<std::string>& messages, const char* what) {
    int n = 0;
    for (const std::string& m : messages)
        n += m.find(what) != std::string::npos;
    return n;
}

/// hsmu replay --import FILE --identify with {"model": {"law": "boucWenPinching"}} (the default
/// online method, the pinching UKF) ends within 1.25 x the pinching calibration without a
/// divergence. calibration: the pinching calibration's NRMSE on the record when known (else computed).
inline void onlineWithinAQuarterOf(const QString& file, std::optional<double> calibration = {}) {
    SpecimenHistory h;
    if (!readRecord(file.toStdString(), h))
        QSKIP(qPrintable("shared record absent: " + file));
    const nlohmann::json config = {{"model", {{"law", "boucWenPinching"}}}};
    IdentificationSettings s = withOverride(defaultIdentificationSettings(), config, "test");
    QCOMPARE(s.updating.method, std::string("ukf"));
    s.calibrate = !calibration.has_value();
    const OfflineIdentificationResult r = identifyOffline(h, s);
    QVERIFY(calibration || (r.calibration && r.calibration->ok));
    // the calibration of the law without offsets: what the online filter fits (it takes none;
    // the default offline calibration may add them, docs/method.md "Offsets")
    const double best = calibration                      ? *calibration
                        : r.calibration->offsetTest.ran ? r.calibration->offsetTest.nrmseWithout
                                                        : r.calibration->nrmse;
    const int divergences = count(r.messages, "diverging");
    qInfo("%s, pinching: calibration NRMSE %.4f, online pinching UKF final NRMSE %.4f "
          "(%.3fx), %d anchors, %d divergences, zetaS %.3f",
          qPrintable(QFileInfo(file).fileName()), best, r.finalNrmse, r.finalNrmse / best, count(r.messages, "anchor"), divergences,
          r.finalEstimate.at("zetaS"));
    if (qEnvironmentVariableIsSet("HSMU_VERBOSE")) {
        for (const std::string& m : r.messages)
            qInfo("  %s", m.c_str());
        for (const auto& [name, v] : r.finalEstimate)
            qInfo("  online %s = %.5g (calibration %.5g)", name.c_str(), v,
                  r.calibration && r.calibration->parameters.count(name)
                      ? r.calibration->parameters.at(name)
                      : NAN);
    }
    QCOMPARE(r.method, std::string("UKF (pinching)"));
    QVERIFY2(r.finalNrmse <= 1.25 * best,
             qPrintable(QString("online NRMSE %1 > 1.25 x %2").arg(r.finalNrmse).arg(best)));
    QCOMPARE(divergences, 0);
}

} // namespace hsmu::test
