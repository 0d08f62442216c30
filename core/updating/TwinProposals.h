#pragma once
// TwinProposals: the damper twin's updates approved by the operator (docs/rths.md, "Proposals
// approved by the console"); in core/updating, beside the approval model it takes. With `"identification": {"approve": true}` the online
// identification's offers (TwinIdentification, or any TwinUpdateSource) do not reach the twin
// at once: each becomes a proposal the operator approves or rejects, in the hybrid test's
// approval model (Reporter.h, policy OnApproval; its UpdateProposal and UpdateDecision):
//
//   - one proposal per target (the twin) is pending at a time: an offer made while one is
//     pending supersedes it (its event: Superseded, "superseded by proposal #N"), so an
//     approval always applies the latest estimate the operator saw;
//   - approve(id) checks the proposal now with the loop's own check (checkTwinUpdate: the box,
//     the law): refused, it is never applied (event Refused, the reason); accepted, it is
//     applied before the loop's next tick (event Applied, its proposal id, at that tick);
//   - reject(id): event Rejected at the next tick, nothing applied;
//   - every event (Proposed when made, Superseded, Rejected, Refused, Applied) carries the
//     proposal's id and the tick the loop learnt of it, for the record's notes, the monitor and
//     the summary (RthsRunner hands them to the run's observer).
// The operator's calls come from another thread (the controller's io thread): a mutex guards the
// queue; at the real-time pace (`blocking` false) the loop only tries it, never waits (a busy
// lock: the next tick looks again).

#include "core/rths/DamperTwin.h"
#include "core/updating/Reporter.h"

#include <deque>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::rths {

class TwinProposals final : public TwinUpdateSource {
public:
    /// offers: where the estimates come from (not owned, outlives this); damper: the twin's
    /// settings (its box); rate [Hz] for the events' times.
    TwinProposals(TwinUpdateSource& offers, const DamperSettings& damper, double rate, bool blocking);

    // The loop's thread.
    bool next(long k, TwinUpdate& out) override;
    bool nextEvent(long k, UpdateEvent& out) override;
    void observe(long k, double deformation, double force) override { m_offers.observe(k, deformation, force); }

    // Any thread.
    /// Approve proposal `id`: "" when it will be applied before the loop's next tick, else why
    /// not (no such pending proposal, superseded, outside the box or refused by the law: then
    /// removed and recorded as Refused, never applied).
    std::string approve(int id);
    /// Reject proposal `id`: "" when rejected, else why not (no such pending proposal).
    std::string reject(int id);
    /// The proposals waiting for the operator (at most one).
    std::vector<UpdateProposal> pending() const;

private:
    UpdateEvent event(const UpdateProposal& p, UpdateDecision d, const std::string& message) const;
    /// Why proposal `id` is not pending (superseded by #N, decided, unknown).
    std::string notPending(int id) const;

    TwinUpdateSource& m_offers;
    DamperSettings m_damper;
    double m_h;
    bool m_blocking;
    mutable std::mutex m_mutex;
    std::deque<UpdateProposal> m_pending;
    std::deque<TwinUpdate> m_approved;
    std::deque<UpdateEvent> m_events; // decided, for the loop's next tick (step set there)
    std::vector<std::pair<int, int>> m_superseded; // (old id, new id)
    int m_nextId = 1;
};

} // namespace hsmu::rths
