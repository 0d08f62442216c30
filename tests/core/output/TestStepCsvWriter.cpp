// StepCsvWriter: header with units, one row per committed step equal to the StepRecords (to
// the 10 significant digits written), periodic flushing.

#include "OutputFixture.h"

#include "core/output/RunLayout.h"
#include "core/output/StepCsvWriter.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

std::vector<std::string> readLines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::vector<double> parseRow(const std::string& line) {
    std::vector<double> values;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, ',');)
        values.push_back(std::stod(field));
    return values;
}

/// Equal to the 10 significant digits of "%.10g".
bool sameTo10Digits(double written, double exact) {
    if (std::isnan(exact))
        return std::isnan(written);
    return std::abs(written - exact) <= 6e-10 * std::abs(exact) + 1e-300;
}

} // namespace

class TestStepCsvWriter : public QObject {
    Q_OBJECT
private slots:
    void headerNamesUnits() {
        auto test = smallFrame();
        const std::string h = StepCsvWriter::header(RunLayout::of(test->structure()));
        QCOMPARE(QString::fromStdString(h),
                 QStringLiteral("time_s,ag_m_s2,D1_u_m,D1_v_m_s,D1_a_m_s2,D2_u_m,D2_v_m_s,"
                                "D2_a_m_s2,E1_deformation_rad,E1_force_kNm,E1_commanded_rad,"
                                "E2_deformation_rad,E2_force_kNm,E3_deformation_m,E3_force_kN"));
    }

    void rowsEqualRecords() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath(QStringLiteral("steps.csv")).toStdString();
        auto test = smallFrame(0.5);
        const RunLayout layout = RunLayout::of(test->structure());
        Collector collector;
        {
            StepCsvWriter writer(path, layout);
            test->addObserver(&writer);
            test->addObserver(&collector);
            QVERIFY2(test->prepare(), test->lastError().c_str());
            while (test->step() == HybridTest::StepResult::Advanced) {
            }
            QCOMPARE(test->state(), HybridTest::State::Finished);
            test->removeObserver(&writer);
            QVERIFY(writer.finish());
            QCOMPARE(writer.rowsWritten(), 51);
        }
        const auto lines = readLines(path);
        QCOMPARE(lines.size(), collector.records.size() + 1);
        QCOMPARE(collector.records.size(), std::size_t(51)); // steps 0..50
        bool someNonZero = false;
        for (std::size_t k = 0; k < collector.records.size(); ++k) {
            const StepRecord& r = collector.records[k];
            std::vector<double> expected{r.time, r.groundAcceleration};
            for (Eigen::Index i = 0; i < r.u.size(); ++i)
                expected.insert(expected.end(), {r.u[i], r.v[i], r.a[i]});
            for (std::size_t e = 0; e < r.elements.size(); ++e) {
                expected.insert(expected.end(), {r.elements[e].deformation, r.elements[e].force});
                if (layout.elements[e].experimental)
                    expected.push_back(r.elements[e].commanded);
            }
            const std::vector<double> row = parseRow(lines[k + 1]);
            QCOMPARE(row.size(), expected.size());
            for (std::size_t c = 0; c < row.size(); ++c) {
                QVERIFY2(sameTo10Digits(row[c], expected[c]),
                         qPrintable(QStringLiteral("row %1 column %2: %3 vs %4")
                                        .arg(k)
                                        .arg(c)
                                        .arg(row[c], 0, 'g', 17)
                                        .arg(expected[c], 0, 'g', 17)));
                someNonZero = someNonZero || expected[c] != 0.0;
            }
        }
        QVERIFY(someNonZero);
        // The specimen's force column is the measured force, not the numerical model's.
        QVERIFY(std::abs(collector.records.back().elements[0].force) > 0.0);
    }

    void updatingColumnsFollowTheRecords() {
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("steps.csv")).toStdString();
        auto test = buildHybridTest(condition3(0.5));
        const RunLayout layout = RunLayout::of(*test);
        QVERIFY(layout.updating.has_value());
        QCOMPARE(layout.updating->specimen, std::string("Element 1"));
        QCOMPARE(layout.updating->parameters.size(), std::size_t(7));
        const std::string h = StepCsvWriter::header(layout);
        const std::string base = StepCsvWriter::header(RunLayout::of(test->structure()));
        QCOMPARE(QString::fromStdString(h.substr(base.size())),
                 QStringLiteral(",param_k0,param_alpha,param_beta,param_gamma,param_n,"
                                "param_deltaNu,param_deltaEta,std_k0,std_alpha,std_beta,std_gamma,"
                                "std_n,std_deltaNu,std_deltaEta,aux_force_kNm,fit_error"));
        Collector collector;
        {
            StepCsvWriter writer(path, layout);
            test->addObserver(&writer);
            test->addObserver(&collector);
            QVERIFY2(test->prepare(), test->lastError().c_str());
            while (test->step() == HybridTest::StepResult::Advanced) {
            }
            test->removeObserver(&writer);
            QVERIFY(writer.finish());
        }
        const auto lines = readLines(path);
        QCOMPARE(lines.size(), collector.records.size() + 1);
        const std::size_t first = parseRow(lines[1]).size() - 16;
        for (std::size_t k = 0; k < collector.records.size(); ++k) {
            const UpdatingSample& u = collector.records[k].updating;
            QVERIFY(collector.records[k].hasUpdating);
            std::vector<double> expected = u.parameters;
            expected.insert(expected.end(), u.stddev.begin(), u.stddev.end());
            expected.insert(expected.end(), {u.auxiliaryForce, u.fitError});
            const std::vector<double> row = parseRow(lines[k + 1]);
            for (std::size_t c = 0; c < expected.size(); ++c)
                QVERIFY2(sameTo10Digits(row[first + c], expected[c]),
                         qPrintable(QStringLiteral("row %1 column %2").arg(k).arg(first + c)));
        }
        // The estimate moves and the auxiliary model carries force.
        QVERIFY(collector.records.back().updating.parameters !=
                collector.records.front().updating.parameters);
        QVERIFY(std::abs(collector.records.back().updating.auxiliaryForce) > 0.0);
    }

    void recordWithoutUpdatingWritesNan() {
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("steps.csv")).toStdString();
        RunLayout layout;
        layout.dofNames = {"D"};
        layout.updating = UpdatingInfo{"S", "UKF", {"k0"}, {"m", "kN"}};
        StepCsvWriter writer(path, layout);
        StepRecord r;
        r.u = r.v = r.a = Eigen::VectorXd::Constant(1, 0.5);
        writer.onStep(r);
        r.hasUpdating = true;
        r.updating.parameters = {1.25};
        r.updating.stddev = {0.125};
        r.updating.auxiliaryForce = -2.0;
        r.updating.fitError = 0.03;
        writer.onStep(r);
        QVERIFY(writer.finish());
        const auto lines = readLines(path);
        QCOMPARE(lines.size(), std::size_t(3));
        QCOMPARE(lines[0], std::string("time_s,ag_m_s2,D_u_m,D_v_m_s,D_a_m_s2,param_k0,std_k0,"
                                       "aux_force_kN,fit_error"));
        QCOMPARE(lines[1], std::string("0,0,0.5,0.5,0.5,nan,nan,nan,nan"));
        QCOMPARE(lines[2], std::string("0,0,0.5,0.5,0.5,1.25,0.125,-2,0.03"));
    }

    void flushesEveryThousandRows() {
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("steps.csv")).toStdString();
        RunLayout layout;
        layout.dofNames = {"D"};
        StepCsvWriter writer(path, layout);
        StepRecord r;
        r.u = r.v = r.a = Eigen::VectorXd::Constant(1, 0.125);
        for (int i = 0; i < StepCsvWriter::kFlushInterval + 10; ++i) {
            r.step = i;
            r.time = 0.01 * i;
            writer.onStep(r);
        }
        // Before finish(): at least the first 1000 rows are on disk (plus the header).
        QVERIFY(readLines(path).size() >= std::size_t(StepCsvWriter::kFlushInterval + 1));
        QVERIFY(writer.finish());
        QCOMPARE(readLines(path).size(), std::size_t(StepCsvWriter::kFlushInterval + 11));
        QCOMPARE(readLines(path)[2], std::string("0.01,0,0.125,0.125,0.125"));
    }

    void unwritablePathThrows() {
        RunLayout layout;
        QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                                 StepCsvWriter("/nonexistent-dir/x/steps.csv", layout));
    }
};

QTEST_APPLESS_MAIN(TestStepCsvWriter)
#include "TestStepCsvWriter.moc"
