// Tests of UnscentedKalmanFilter (core/identification/UnscentedKalmanFilter.h).
// On a linear-Gaussian problem the UKF must equal the Kalman filter (written out below)
// to 1e-9 relative, with the paper's a = 1e-4 (weights ~1e7 of both signs: this checks the
// deviation-form sums) and with a = 1. The guarded cases must reject the step and keep the
// last good x and P exactly.
// UkfFault is compared with QVERIFY(a == b): QCOMPARE would look for a toString by ADL.

#include "core/identification/UnscentedKalmanFilter.h"
#include "core/util/PortableRandom.h"

#include <Eigen/LU>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

namespace {

// Constant-velocity model: x = [position, velocity], dt = 0.1 s, white acceleration q.
constexpr double kDt = 0.1;
constexpr double kQ = 0.05;
constexpr double kR = 0.04;

Matrix transition() {
    Matrix F(2, 2);
    F << 1.0, kDt, 0.0, 1.0;
    return F;
}

Matrix processNoise() {
    Matrix Q(2, 2);
    Q << kDt * kDt * kDt / 3.0, kDt * kDt / 2.0, kDt * kDt / 2.0, kDt;
    return kQ * Q;
}

double relativeError(const Matrix& a, const Matrix& b) {
    return (a - b).norm() / b.norm();
}

// Runs 200 predict/update steps of the UKF and of the textbook Kalman filter on the same
// measurements; returns the largest relative difference of x and of P over the run.
std::pair<double, double> compareWithKalman(double a, bool inPlaceForm) {
    const Matrix F = transition();
    const Matrix Q = processNoise();
    Matrix H(1, 2);
    H << 1.0, 0.0;
    const Matrix R = Matrix::Constant(1, 1, kR);

    Vector x0(2);
    x0 << 0.3, -0.2;
    Matrix P0(2, 2);
    P0 << 1.0, 0.2, 0.2, 0.5;

    UkfSettings settings;
    settings.a = a;
    UnscentedKalmanFilter ukf(settings);
    if (!ukf.init(x0, P0).ok || !ukf.setProcessNoise(Q).ok || !ukf.setMeasurementNoise(R).ok) {
        return {1.0, 1.0};
    }
    Vector x = x0;
    Matrix P = P0;

    PortableRandom random(17);
    double truePosition = 0.0;
    const double trueVelocity = 0.4;
    double worstX = 0.0, worstP = 0.0;
    for (int k = 0; k < 200; ++k) {
        truePosition += trueVelocity * kDt;
        Vector z(1);
        z << truePosition + std::sqrt(kR) * random.normal();

        // Kalman filter.
        x = F * x;
        P = F * P * F.transpose() + Q;
        const Matrix S = H * P * H.transpose() + R;
        const Matrix K = P * H.transpose() * S.inverse();
        x += K * (z - H * x);
        P = (Matrix::Identity(2, 2) - K * H) * P;
        P = 0.5 * (P + P.transpose()).eval();

        // UKF, through either call form.
        UkfStatus predicted, updated;
        if (inPlaceForm) {
            predicted = ukf.predict(
                [&](const Eigen::Ref<const Vector>& s, Eigen::Ref<Vector> out) { out = F * s; });
            updated = ukf.update(
                [&](const Eigen::Ref<const Vector>& s, Eigen::Ref<Vector> out) {
                    out = H * s;
                    return true;
                },
                z);
        } else {
            predicted = ukf.predict([&](const Vector& s) -> Vector { return F * s; });
            updated = ukf.update([&](const Vector& s) -> Vector { return H * s; }, z);
        }
        if (!predicted.ok || !updated.ok) {
            return {1.0, 1.0};
        }
        worstX = std::max(worstX, relativeError(ukf.state(), x));
        worstP = std::max(worstP, relativeError(ukf.covariance(), P));
    }
    return {worstX, worstP};
}

Vector vec2(double a, double b) {
    Vector v(2);
    v << a, b;
    return v;
}

} // namespace

class TestUnscentedKalmanFilter : public QObject {
    Q_OBJECT

private slots:
    void equalsKalmanFilterWithPaperSetting();
    void equalsKalmanFilterWithUnitSpread();
    void nonFiniteMeasurementIsRejected();
    void failingFunctionIsRejected();
    void indefiniteProcessNoiseIsRejected();
    void singularCovarianceUsesJitter();
    void invalidSettingsAndDimensions();
    void zeroVarianceComponentStaysExact();
    void projectionHoldsBounds();
    void allSigmaPointsFormEqualsPerPointForm();
};

void TestUnscentedKalmanFilter::equalsKalmanFilterWithPaperSetting() {
    for (const bool inPlace : {false, true}) {
        const auto [dx, dp] = compareWithKalman(1e-4, inPlace);
        qInfo("a = 1e-4, %s form: max rel. error x %.3g, P %.3g",
              inPlace ? "in-place" : "returning", dx, dp);
        QVERIFY2(dx <= 1e-9, qPrintable(QString("x rel. error %1").arg(dx)));
        QVERIFY2(dp <= 1e-9, qPrintable(QString("P rel. error %1").arg(dp)));
    }
}

void TestUnscentedKalmanFilter::equalsKalmanFilterWithUnitSpread() {
    const auto [dx, dp] = compareWithKalman(1.0, false);
    qInfo("a = 1: max rel. error x %.3g, P %.3g", dx, dp);
    QVERIFY2(dx <= 1e-9, qPrintable(QString("x rel. error %1").arg(dx)));
    QVERIFY2(dp <= 1e-9, qPrintable(QString("P rel. error %1").arg(dp)));
    // kappa = 0 and b = 0 (other weights) must still agree: linear problems are exact for any.
    UkfSettings settings;
    settings.a = 0.5;
    settings.kappa = 0.0;
    settings.b = 0.0;
    UnscentedKalmanFilter ukf(settings);
    QVERIFY(ukf.init(vec2(1.0, 2.0), Matrix::Identity(2, 2)).ok);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return transition() * s; }).ok);
    const Matrix expected = transition() * transition().transpose();
    QVERIFY(relativeError(ukf.covariance(), expected) <= 1e-12);
    QVERIFY(relativeError(ukf.state(), transition() * vec2(1.0, 2.0)) <= 1e-12);
}

void TestUnscentedKalmanFilter::nonFiniteMeasurementIsRejected() {
    UnscentedKalmanFilter ukf;
    QVERIFY(ukf.init(vec2(1.0, 0.5), Matrix::Identity(2, 2)).ok);
    QVERIFY(ukf.setProcessNoise(processNoise()).ok);
    QVERIFY(ukf.setMeasurementNoise(Matrix::Constant(1, 1, kR)).ok);
    const auto f = [](const Vector& s) -> Vector { return transition() * s; };
    const auto h = [](const Vector& s) -> Vector { return s.head(1); };
    for (int k = 0; k < 5; ++k) {
        QVERIFY(ukf.predict(f).ok);
        QVERIFY(ukf.update(h, Vector::Constant(1, 0.1 * k)).ok);
    }
    QVERIFY(ukf.predict(f).ok);
    const Vector x = ukf.state();
    const Matrix P = ukf.covariance();
    // NaN only away from the centre point: a sigma point, not the mean, fails.
    const UkfStatus status = ukf.update(
        [&](const Vector& s) -> Vector {
            return Vector::Constant(1,
                                    s(0) > x(0) ? std::numeric_limits<double>::quiet_NaN() : s(0));
        },
        Vector::Constant(1, 0.7));
    QVERIFY(!status.ok);
    QVERIFY(status.fault == UkfFault::NonFiniteValue);
    QVERIFY(!status.reason.empty());
    QVERIFY(ukf.state() == x);
    QVERIFY(ukf.covariance() == P);
    // A NaN measurement is rejected as well, and the filter goes on afterwards.
    QVERIFY(!ukf.update(h, Vector::Constant(1, std::numeric_limits<double>::quiet_NaN())).ok);
    QVERIFY(ukf.state() == x && ukf.covariance() == P);
    QVERIFY(ukf.update(h, Vector::Constant(1, 0.7)).ok);
    QVERIFY(ukf.state().allFinite());
}

void TestUnscentedKalmanFilter::failingFunctionIsRejected() {
    UnscentedKalmanFilter ukf;
    QVERIFY(ukf.init(vec2(1.0, 0.5), Matrix::Identity(2, 2)).ok);
    const Vector x = ukf.state();
    const UkfStatus status =
        ukf.predict([](const Eigen::Ref<const Vector>& s, Eigen::Ref<Vector> out) {
            out = s;
            return s(1) < 0.5; // fails for the sigma points above the mean
        });
    QVERIFY(!status.ok);
    QVERIFY(status.fault == UkfFault::FunctionFailed);
    QVERIFY(status.reason.find("sigma point") != std::string::npos);
    QVERIFY(ukf.state() == x);
    // Wrong output size.
    const UkfStatus wrongSize = ukf.predict([](const Vector&) -> Vector { return Vector(3); });
    QVERIFY(wrongSize.fault == UkfFault::DimensionMismatch);
}

void TestUnscentedKalmanFilter::indefiniteProcessNoiseIsRejected() {
    UnscentedKalmanFilter ukf;
    QVERIFY(ukf.init(vec2(1.0, 0.5), 0.01 * Matrix::Identity(2, 2)).ok);
    const Matrix P = ukf.covariance();
    const Vector x = ukf.state();
    Matrix Q(2, 2);
    Q << 1e-3, 0.0, 0.0, -1.0; // clearly indefinite
    QVERIFY(ukf.setProcessNoise(Q).ok);
    const UkfStatus status = ukf.predict([](const Vector& s) -> Vector { return s; });
    QVERIFY(!status.ok);
    QVERIFY(status.fault == UkfFault::NotPositiveDefinite);
    QVERIFY2(status.reason.find("predicted covariance") != std::string::npos,
             status.reason.c_str());
    QVERIFY(ukf.state() == x && ukf.covariance() == P);
    // A merely rounded one (eigenvalue -1e-14 of a variance 1e-2) passes through the jitter.
    Q << 0.0, 0.0, 0.0, -1e-14;
    QVERIFY(ukf.setProcessNoise(Q).ok);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).ok);
}

void TestUnscentedKalmanFilter::singularCovarianceUsesJitter() {
    UnscentedKalmanFilter ukf;
    Matrix P(2, 2);
    P << 1.0, 1.0, 1.0, 1.0; // rank 1: LLT fails, P + 1e-12 I does not
    const UkfStatus status = ukf.init(vec2(0.0, 0.0), P);
    QVERIFY2(status.ok, status.reason.c_str());
    QVERIFY(status.jitter > 0.0 && status.jitter <= 1e-6);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).ok);
    QVERIFY(ukf.update([](const Vector& s) -> Vector { return s.head(1); }, Vector::Ones(1)).ok);
    QVERIFY(ukf.covariance().allFinite());
    // Correlation 1 is kept: both components move together.
    QVERIFY(std::abs(ukf.state()(0) - ukf.state()(1)) <= 1e-5);
    // A negative variance is not a rounding error.
    P << 1.0, 0.0, 0.0, -1e-3;
    const UkfStatus bad = ukf.setState(vec2(0.0, 0.0), P);
    QVERIFY(!bad.ok && bad.fault == UkfFault::NotPositiveDefinite);
}

void TestUnscentedKalmanFilter::invalidSettingsAndDimensions() {
    UnscentedKalmanFilter ukf;
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).fault ==
            UkfFault::NotInitialized);
    QVERIFY(ukf.init(vec2(0.0, 0.0), Matrix::Identity(3, 3)).fault == UkfFault::DimensionMismatch);
    QVERIFY(ukf.init(vec2(0.0, 0.0), Matrix::Identity(2, 2)).ok);
    UkfSettings settings;
    settings.kappa = -3.0; // L + kappa = -1
    ukf.setSettings(settings);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).fault ==
            UkfFault::InvalidSettings);
    settings.kappa.reset();
    settings.a = 0.0;
    ukf.setSettings(settings);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).fault ==
            UkfFault::InvalidSettings);
    ukf.setSettings(UkfSettings{});
    QVERIFY(ukf.setProcessNoise(Matrix::Identity(3, 3)).fault == UkfFault::DimensionMismatch);
    QVERIFY(ukf.update([](const Vector& s) -> Vector { return s; }, Vector::Zero(2)).fault ==
            UkfFault::DimensionMismatch);
    QCOMPARE(std::string(ukfFaultName(UkfFault::NotPositiveDefinite)),
             std::string("not positive definite"));
    // Bounds: the state's size, lower <= upper, no NaN; a refused box changes nothing.
    QVERIFY(ukf.setBounds(Vector::Zero(3), Vector::Ones(3)).fault == UkfFault::DimensionMismatch);
    QVERIFY(ukf.setBounds(vec2(0.0, 1.0), vec2(1.0, 0.5)).fault == UkfFault::InvalidSettings);
    QVERIFY(ukf.setBounds(vec2(0.0, 0.0), vec2(1.0, std::nan(""))).fault ==
            UkfFault::InvalidSettings);
    QVERIFY(!ukf.bounded());
    QVERIFY(ukf.setBounds(vec2(-1.0, -1.0), vec2(1.0, 1.0)).ok && ukf.bounded());
    ukf.clearBounds();
    QVERIFY(!ukf.bounded());
}

void TestUnscentedKalmanFilter::zeroVarianceComponentStaysExact() {
    // Component 1 has zero variance (a locked parameter): it must not move at all.
    UnscentedKalmanFilter ukf;
    Matrix P = Matrix::Zero(3, 3);
    P(0, 0) = 1.0;
    P(2, 2) = 0.5;
    Vector x(3);
    x << 0.1, 0.7, -0.2;
    QVERIFY(ukf.init(x, P).ok);
    Matrix Q = Matrix::Zero(3, 3);
    Q(0, 0) = Q(2, 2) = 1e-3;
    QVERIFY(ukf.setProcessNoise(Q).ok);
    for (int k = 0; k < 20; ++k) {
        QVERIFY(ukf.predict([](const Vector& s) -> Vector {
                       Vector n = s;
                       n(0) += 0.1 * s(1) * s(2);
                       return n;
                   })
                    .ok);
        QVERIFY(
            ukf.update([](const Vector& s) -> Vector { return Vector::Constant(1, s(0) * s(1)); },
                       Vector::Constant(1, 0.3))
                .ok);
        QCOMPARE(ukf.state()(1), 0.7);
        QCOMPARE(ukf.covariance().row(1).cwiseAbs().maxCoeff(), 0.0);
    }
    QCOMPARE(ukf.standardDeviations()(1), 0.0);
}

void TestUnscentedKalmanFilter::projectionHoldsBounds() {
    // Scalar parameter in [0, 1] observed directly; the measurements say 1.5, then 0.5. Sigma
    // points may use the whole box, the means stay 1e-3 inside it; both spreads of a.
    for (const double a : {1e-4, 1.0}) {
        UkfSettings settings;
        settings.a = a;
        UnscentedKalmanFilter ukf(settings);
        QVERIFY(ukf.init(Vector::Constant(1, 0.5), Matrix::Constant(1, 1, 0.25)).ok);
        QVERIFY(ukf.setProcessNoise(Matrix::Constant(1, 1, 1e-4)).ok);
        QVERIFY(ukf.setMeasurementNoise(Matrix::Constant(1, 1, 0.01)).ok);
        double lowest = 1.0, highest = 0.0;
        QVERIFY(ukf.setBounds(Vector::Constant(1, 0.0), Vector::Constant(1, 1.0),
                              Vector::Constant(1, 1e-3), Vector::Constant(1, 1.0 - 1e-3))
                    .ok);
        const auto h = [&](const Vector& s) -> Vector {
            lowest = std::min(lowest, s(0));
            highest = std::max(highest, s(0));
            return s;
        };
        for (int k = 0; k < 100; ++k) {
            const double z = k < 50 ? 1.5 : 0.5;
            QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).ok);
            QVERIFY(ukf.update(h, Vector::Constant(1, z)).ok);
            QVERIFY(ukf.state()(0) >= 1e-3 && ukf.state()(0) <= 1.0 - 1e-3);
            QVERIFY(ukf.covariance()(0, 0) > 0.0 && ukf.covariance().allFinite());
            if (k == 49) {
                QVERIFY2(ukf.state()(0) >= 0.99, qPrintable(QString::number(ukf.state()(0))));
            }
        }
        QVERIFY(lowest >= 0.0 && highest <= 1.0);
        // Off the bound again: the steady-state gain is ~0.1, 50 steps bring it within 0.05.
        QVERIFY2(std::abs(ukf.state()(0) - 0.5) <= 0.05,
                 qPrintable(QString("a %1: %2").arg(a).arg(ukf.state()(0))));
    }
    // A mean on the bound with one hook: the pair is dropped, the estimate cannot leave the
    // box; the prediction loses that direction's variance but Q brings it back (never 0).
    UnscentedKalmanFilter ukf;
    QVERIFY(ukf.init(Vector::Constant(1, 1.0), Matrix::Constant(1, 1, 0.01)).ok);
    QVERIFY(ukf.setProcessNoise(Matrix::Constant(1, 1, 1e-4)).ok);
    QVERIFY(ukf.setBounds(Vector::Constant(1, 0.0), Vector::Constant(1, 1.0)).ok);
    QVERIFY(ukf.predict([](const Vector& s) -> Vector { return s; }).ok);
    QVERIFY(ukf.update([](const Vector& s) -> Vector { return s; }, Vector::Constant(1, 2.0)).ok);
    QCOMPARE(ukf.state()(0), 1.0);
    QCOMPARE(ukf.covariance()(0, 0), 1e-4);
}

void TestUnscentedKalmanFilter::allSigmaPointsFormEqualsPerPointForm() {
    // The same filter through the per-point and the all-points forms: identical x and P, bit
    // for bit (the functions do the same arithmetic per point). A failure is reported at the
    // point the all-points function names, and x and P are kept.
    const auto move = [](const auto& s, auto&& out) {
        out(0) = s(0) + kDt * s(1);
        out(1) = s(1);
    };
    const auto moveAll = [&](const Matrix& s, Matrix& out) -> Eigen::Index {
        for (Eigen::Index i = 0; i < s.cols(); ++i) {
            move(s.col(i), out.col(i));
        }
        return -1;
    };
    UnscentedKalmanFilter one, all;
    for (UnscentedKalmanFilter* ukf : {&one, &all}) {
        QVERIFY(ukf->init(vec2(0.3, -0.2), Matrix::Identity(2, 2)).ok);
        QVERIFY(ukf->setProcessNoise(processNoise()).ok);
    }
    const auto position = [](const Eigen::Ref<const Vector>& s, Eigen::Ref<Vector> out) {
        out(0) = s(0);
    };
    for (int k = 0; k < 20; ++k) {
        const Vector z = Vector::Constant(1, 0.04 * k);
        QVERIFY(one.predict([&](const Eigen::Ref<const Vector>& s, Eigen::Ref<Vector> out) {
                       move(s, out);
                   })
                    .ok);
        QVERIFY(all.predict(AllSigmaPoints{moveAll}).ok);
        QVERIFY(one.update(position, z).ok && all.update(position, z).ok);
        QVERIFY(one.state() == all.state() && one.covariance() == all.covariance());
    }
    const Vector x = all.state();
    const UkfStatus failed =
        all.predict(AllSigmaPoints{[](const Matrix&, Matrix&) -> Eigen::Index { return 3; }});
    QVERIFY(!failed.ok && failed.fault == UkfFault::FunctionFailed);
    QVERIFY(failed.reason.find("sigma point 3") != std::string::npos);
    QVERIFY(all.state() == x);
}

QTEST_APPLESS_MAIN(TestUnscentedKalmanFilter)
#include "TestUnscentedKalmanFilter.moc"
