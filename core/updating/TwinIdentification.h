#pragma once
// TwinIdentification: the online identification of the RTHS specimen's MR damper, off the
// loop's thread, whose accepted estimates update the damper's twin at tick boundaries
// (docs/rths.md, "A damper and its twin"). The identifier is the mrDamper UKF of the updating
// (MrDamperUkfIdentifier: the anchored filter of AnchoredUkf.h), started from the twin's law in
// the twin's scales uRef / fRef, its user bounds the twin's parameter box:
//
//   - the loop hands it every `decimation`-th tick's measured deformation xm [m] and damper
//     force [N] (ticks 0, d, 2d, ...: the identifier's step is d h) through a bounded
//     single-producer ring; the loop never waits on it at the real-time pace;
//   - a worker thread steps the identifier; after sample i = m I (I = interval / (d h),
//     m = 1, 2, ...), when the estimate is reportable, it offers all of it (c0 ... fRef) as an
//     update due at tick i d + L, L = latency / h (the identification's time, fixed in ticks);
//   - next(k) hands over the offers due at or before k. With `wait` (the simulated pace) the
//     loop waits at a tick k = m I d + L until the worker has taken sample m I: the run is a
//     function of its inputs alone, bit for bit. Without it (the real-time pace) an offer not
//     ready at its tick is applied at the first tick after it is (the event names that tick),
//     and a sample that finds the ring full is dropped and counted.
// The offers are checked and applied by the loop (RthsLoop::updateTwin: the box, the law's
// admissibility, all or nothing); what it refuses is an event too.

#include "core/rths/DamperTwin.h"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace hsmu::rths {

struct TwinIdentificationSettings {
    bool enabled = false;
    int decimation = 4;    ///< ticks per identifier sample (>= 1)
    double interval = 1.0; ///< [s] of test time between two offers (> 0)
    double latency = 0.25; ///< [s] from an offer's last sample to its tick (>= 0)
    bool wait = true;      ///< the simulated pace (see above); false at the real-time pace
    /// The offers wait for the operator's approval (TwinProposals.h) instead of being applied
    /// at their tick ("approve": true; hsmu-controller --rths).
    bool approve = false;
};

class TwinIdentification final : public TwinUpdateSource {
public:
    /// Throws std::invalid_argument for settings out of range or a damper without a twin.
    TwinIdentification(const DamperSettings& damper, const TwinIdentificationSettings& s,
                       double rate);
    ~TwinIdentification() override; ///< stops the worker (a running anchor job is cancelled)

    bool next(long k, TwinUpdate& out) override;
    void observe(long k, double deformation, double force) override;

    /// Every offer made so far, in order (for reports and tests; locks).
    std::vector<TwinUpdate> offers() const;
    long samplesDropped() const;
    /// Why the identification stopped early ("" while it works).
    std::string failure() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace hsmu::rths
