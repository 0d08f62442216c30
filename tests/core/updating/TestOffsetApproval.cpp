// The twins' offsets (docs/method.md, "Offsets", Online): the paper's frame (preset
// paper-condition-3) with a virtual specimen whose load cell reads a bias F0 = 3 kN m (15 % of
// fRef) and updating.offsets auto. The offset check proposes the offsets as their own pending
// item; without the operator's approval the twin is unchanged bit for bit (the headless
// approveAll flag included), and after it the twin's moment is F_law(u - u0) + F0.
#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/hysteresis/OffsetLaw.h"
#include "core/structure/Structure.h"
#include "core/updating/ModelUpdater.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace hsmu;

namespace {
constexpr double kBias = 3.0; // [kN m] the virtual load cell's bias

TestConfig biasedFrame(const std::string& offsets, const std::string& approval)
{
    TestConfig cfg = loadConfigFile(std::string(HSMU_SOURCE_DIR) +
                                    "/resources/presets/paper-condition-3.json");
    cfg.analysis.duration = 9.0;
    for (auto& e : cfg.elements)
        if (e.name == "Element 1")
            e.specimen.trueMaterial.params[OffsetLaw::kForceOffset] = kBias;
    cfg.updating.offsets = offsets;
    cfg.updating.policy = ReporterPolicy::OnApproval;
    cfg.updating.approval = approval;
    return cfg;
}

/// Steps until the offsets are pending (or `limit` steps); the twin's committed moments.
std::vector<double> runUntilOffsets(HybridTest& test, int limit)
{
    std::vector<double> twin;
    const Element* e = test.structure().element("Element 2");
    for (int i = 0; i < limit && !test.updater()->pendingOffsets(); ++i) {
        test.step();
        twin.push_back(e->law()->committedForce());
    }
    return twin;
}
} // namespace

class TestOffsetApproval : public QObject {
    Q_OBJECT
private slots:
    void offsetsWaitForTheOperatorAndApplyAsOffsetLaw()
    {
        // Reference: the same run without the check.
        auto plain = buildHybridTest(biasedFrame("off", "approveAll"));
        QVERIFY(plain->prepare());
        auto test = buildHybridTest(biasedFrame("auto", "approveAll"));
        QVERIFY(test->prepare());
        const std::vector<double> withCheck = runUntilOffsets(*test, 900);
        const OffsetProposal* p = test->updater()->pendingOffsets();
        QVERIFY2(p, qPrintable(QString::fromStdString(
                        test->updater()->offsetCheck()->lastMessage())));
        qInfo("offsets #%d at step %d on %zu samples: u0 = %.4g rad (sd %.2g), F0 = %.4g kN m "
              "(sd %.2g); NRMSE %.4f without, %.4f with, %d branches, criterion %.3g",
              p->id, p->step, p->samples, p->deformationOffset, p->deformationSd, p->forceOffset,
              p->forceSd, p->nrmseWithout, p->nrmseWith, p->branches, p->criterion);
        // The check found the load cell's bias (the specimen has no deformation offset).
        QVERIFY2(std::abs(p->forceOffset - kBias) < 0.1 * kBias,
                 qPrintable(QStringLiteral("F0 %1").arg(p->forceOffset)));
        QVERIFY(std::isfinite(p->forceSd) && p->forceSd > 0.0);
        QVERIFY(p->criterion < 0.0 && p->nrmseWith < p->nrmseWithout);
        // Not applied although every law-parameter proposal is approved (approveAll): the
        // twin followed the same moments as the run without the check, bit for bit.
        const std::vector<double> without = runUntilOffsets(*plain, int(withCheck.size()));
        QCOMPARE(without.size(), withCheck.size());
        for (std::size_t k = 0; k < without.size(); ++k)
            QVERIFY2(without[k] == withCheck[k], qPrintable(QStringLiteral("step %1").arg(k)));
        Element* twin = test->structure().element("Element 2");
        QVERIFY(!dynamic_cast<const OffsetLaw*>(twin->law()));
        for (int i = 0; i < 20; ++i) { // still pending, still not applied
            test->step();
            plain->step();
            QCOMPARE(twin->law()->committedForce(),
                     plain->structure().element("Element 2")->law()->committedForce());
        }
        QVERIFY(test->updater()->pendingOffsets());

        // A wrong id is refused with the reason; the proposal stays.
        std::string error;
        QVERIFY(!test->approveOffsets(p->id + 1, &error));
        QVERIFY2(error.find("not pending") != std::string::npos, error.c_str());
        const OffsetProposal approved = *p;
        const std::unique_ptr<HysteresisLaw> before = twin->law()->clone();
        QVERIFY2(test->approveOffsets(approved.id, &error), error.c_str());
        QVERIFY(!test->updater()->pendingOffsets());
        const auto* wrapped = dynamic_cast<const OffsetLaw*>(twin->law());
        QVERIFY(wrapped);
        QCOMPARE(wrapped->deformationOffset(), approved.deformationOffset);
        QCOMPARE(wrapped->forceOffset(), approved.forceOffset);
        // After the approval: F = F_law(u - u0) + F0, the law continuing from its state.
        std::unique_ptr<HysteresisLaw> reference = before->clone();
        double largest = 0.0;
        for (int i = 0; i < 60; ++i) {
            test->step();
            const double u = twin->law()->committedDeformation();
            QCOMPARE(reference->setTrialDeformation(u - approved.deformationOffset), LawStatus::Ok);
            reference->commit();
            const double expected = reference->committedForce() + approved.forceOffset;
            largest = std::max(largest, std::abs(expected));
            QVERIFY2(std::abs(twin->law()->committedForce() - expected) <= 1e-12 * (1.0 + largest),
                     qPrintable(QStringLiteral("step %1: %2 vs %3")
                                    .arg(i)
                                    .arg(twin->law()->committedForce())
                                    .arg(expected)));
        }
        // The law-parameter updates still reach the wrapped twin (the reporter rebound it).
        QVERIFY(test->updater()->reporter().appliedCount() > 0);
    }

    void rejectedOffsetsLeaveTheTwin()
    {
        auto test = buildHybridTest(biasedFrame("on", "manual"));
        QVERIFY(test->prepare());
        runUntilOffsets(*test, 900);
        const OffsetProposal* p = test->updater()->pendingOffsets();
        QVERIFY(p);
        const int id = p->id;
        QVERIFY(test->rejectOffsets(id));
        QVERIFY(!test->rejectOffsets(id));
        std::string error;
        QVERIFY(!test->approveOffsets(id, &error));
        QVERIFY(!dynamic_cast<const OffsetLaw*>(test->structure().element("Element 2")->law()));
    }

    void configRefusesAnUnknownMode()
    {
        const QString path = QDir::temp().filePath(QStringLiteral("hsmu-offsets-mode.json"));
        QFile in(QString::fromUtf8(HSMU_SOURCE_DIR) +
                 QStringLiteral("/resources/presets/paper-condition-3.json"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray json = in.readAll();
        json.replace("\"updating\": {", "\"updating\": {\n    \"offsets\": \"sometimes\",");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(json);
        out.close();
        try {
            loadConfigFile(path.toStdString());
            QFAIL("accepted offsets 'sometimes'");
        } catch (const std::exception& e) {
            QVERIFY2(std::string(e.what()).find("offsets") != std::string::npos, e.what());
        }
        QFile::remove(path);
    }
};

QTEST_GUILESS_MAIN(TestOffsetApproval)
#include "TestOffsetApproval.moc"
