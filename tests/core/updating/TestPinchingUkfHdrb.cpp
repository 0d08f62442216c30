// The pinching UKF on the HDRB bearing (26,379 samples; docs/validation.md, pinching table):
// online within 1.25 x the pinching calibration's NRMSE, 0.1071 (asserted by
// test_identification_real_pinching_hdrb; not recomputed here: about 30 s of CPU), with no
// divergence; the anchors run on the worker within their budget. A test of its own (about a
// minute) so that test_updating_pinchingukf stays short.

#include "PinchingUkfOnRecords.h"

#include <QtTest>

using namespace hsmu;

class TestPinchingUkfHdrb : public QObject {
    Q_OBJECT

private slots:
    void onlineOnTheHdrbBearing() {
        test::onlineWithinAQuarterOf(QString(HSMU_SHARED_DATA_DIR) +
                                         "/hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt",
                                     0.1071);
    }
};

QTEST_APPLESS_MAIN(TestPinchingUkfHdrb)
#include "TestPinchingUkfHdrb.moc"
