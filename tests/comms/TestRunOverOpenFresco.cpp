// `hsmu run --controller simapp://HOST:PORT` (the real hsmu and hsmu-controller binaries):
// the whole headless run over OpenFresco's SimApp protocol writes the same steps.csv as the
// in-process run (fast pace, ideal actuator, same seed) to 1e-9, and says which protocol and
// sizes it negotiated.
#include "../gui/CliTestSupport.h"
#include "ControllerProcess.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace clitest;

namespace {

const QString kConfig = QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/paper-condition-3.json");

/// steps.csv as rows of numbers (the header row as text in *header).
std::vector<std::vector<double>> numbers(const QString& path, std::string* header) {
    std::ifstream in(path.toStdString());
    std::vector<std::vector<double>> rows;
    std::getline(in, *header);
    for (std::string line; std::getline(in, line);) {
        std::vector<double> row;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            row.push_back(std::strtod(cell.c_str(), nullptr));
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace

class TestRunOverOpenFresco : public QObject {
    Q_OBJECT
private slots:
    void simAppRunEqualsBuiltinRun() {
        ControllerProcess controller({QStringLiteral("--config"), kConfig, QStringLiteral("--pace"),
                                      QStringLiteral("fast"), QStringLiteral("--protocol"),
                                      QStringLiteral("simapp")});
        QVERIFY2(controller.start(), qPrintable(controller.log()));
        QTemporaryDir dir;
        const QString builtin = dir.filePath(QStringLiteral("builtin"));
        const QString linked = dir.filePath(QStringLiteral("simapp"));
        const Result a = hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--duration"),
                               QStringLiteral("2"), QStringLiteral("--out"), builtin});
        QVERIFY2(a.exitCode == 0, qPrintable(report(a)));
        const QString address = QStringLiteral("simapp://127.0.0.1:%1").arg(controller.port());
        const Result b = hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--controller"),
                               address, QStringLiteral("--duration"), QStringLiteral("2"),
                               QStringLiteral("--out"), linked});
        QVERIFY2(b.exitCode == 0, qPrintable(report(b) + controller.log()));
        QVERIFY2(b.err.contains(QStringLiteral("(simapp protocol, plaintext-loopback)")) &&
                     b.err.contains(QStringLiteral("dataSize 256")),
                 qPrintable(b.err));

        std::string hx, hy;
        const auto x = numbers(builtin + QStringLiteral("/steps.csv"), &hx);
        const auto y = numbers(linked + QStringLiteral("/steps.csv"), &hy);
        QCOMPARE(hx, hy);
        QVERIFY(hx.find("param_k0") != std::string::npos); // updating ran on both
        QCOMPARE(x.size(), std::size_t(201));
        QCOMPARE(y.size(), x.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            QCOMPARE(y[i].size(), x[i].size());
            for (std::size_t c = 0; c < x[i].size(); ++c)
                if (!(std::isnan(x[i][c]) && std::isnan(y[i][c])))
                    worst = std::max(worst, std::abs(x[i][c] - y[i][c]));
        }
        QVERIFY2(worst <= 1e-9, qPrintable(QString::number(worst)));
    }
};

QTEST_GUILESS_MAIN(TestRunOverOpenFresco)
#include "TestRunOverOpenFresco.moc"
