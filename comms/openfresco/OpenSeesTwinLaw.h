#pragma once
// OpenSeesTwinLaw: the law of a numerical element whose force OpenSees computes (an OpenSees
// twin, docs/opensees-twins.md). The console keeps the element (its geometry and DOFs); OpenSees
// runs the material as a zeroLength BoucWen in the project's Tcl helper opensees/hsmu_twin.tcl,
// and the Reporter's updates reach it as OpenSees parameters (updateParameter). Why not
// OpenSees' `adapter` element: it reads the next target in the same blocking call that answers
// the previous step's force, so nothing can run between "force sent" and "next step computed",
// and an update made from that force would reach OpenSees one step late.
//
// Per step one round trip: the queued requests of the previous step (commit, revert, param) and
// "trial X" in one write, then one answer "ok F X". X = u / uRef and F = f / fRef: OpenSees
// carries the normalized law, with the configured parameters 1:1 (k0 -> ko, A0 -> Ao); uRef and
// fRef are the console's scales (an update of them acts here only). The displacement is imposed
// exactly (sp constraint, no penalty), so the force is OpenSees' law at exactly X. An increment
// the in-process law splits into N = 2^k equal parts (longer than half a yield deformation,
// BoucWen.h) is sent as "trial X N" and OpenSees runs N equal steps: the same map, so the two
// agree to the Newton tolerances (a split forced by a Newton failure is not mirrored).
//
// A copy of the model law runs alongside (same trials, commits and parameters): trialTangent(),
// algorithmicTangent() and initialTangent() are its (the explicit integrators use only the
// initial one), clone() returns a copy of it (an in-process law). The trial and committed
// forces are OpenSees', except right after a parameter update: the committed force at the kept
// state under the new parameters is the copy's (as BoucWen::setParameters re-evaluates it;
// OpenSees evaluates it at the next trial). The connection is opened at the first trial (retried while refused, up to
// connectTimeout); a lost connection is final: the twin's state lives in that OpenSees process,
// so every later trial fails (the test holds) and the test has to start again with a new one.
// Failures are LawStatus::NoConvergence with failureReason() saying why.
// Thread rules: one thread at a time (like every law).

#include "comms/openfresco/OfSocket.h"
#include "core/hysteresis/HysteresisLaw.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hsmu::comms::of {

struct OpenSeesTwinOptions {
    double connectTimeout = 5.0; ///< [s] to reach a listening helper
    double replyDeadline = 10.0; ///< [s] for each answer (one per step)
};

class OpenSeesTwinLaw final : public HysteresisLaw {
public:
    /// model: the element's configured law (boucWen only: supported() says so).
    OpenSeesTwinLaw(std::string host, std::uint16_t port, std::string element,
                    std::unique_ptr<HysteresisLaw> model, OpenSeesTwinOptions options = {});
    /// Ends the OpenSees session ("bye"; the helper then ends OpenSees).
    ~OpenSeesTwinLaw() override;

    /// "" when a law of this name can be twinned in OpenSees, else why not.
    static std::string supported(const std::string& lawName);

    std::string lawName() const override { return m_model->lawName(); }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_fTrial; }
    double trialTangent() const override { return m_model->trialTangent(); }
    double algorithmicTangent() const override { return m_model->algorithmicTangent(); }
    std::string failureReason() const override { return m_reason; }
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_fCommitted; }
    double initialTangent() const override { return m_model->initialTangent(); }
    void commit() override;
    void revert() override;
    void revertToStart() override;
    std::unique_ptr<HysteresisLaw> clone() const override { return m_model->clone(); }
    std::vector<std::string> parameterNames() const override { return m_model->parameterNames(); }
    double parameterValue(int index) const override { return m_model->parameterValue(index); }
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

    /// Round trips so far (one per trial after the two of the opening).
    long roundTrips() const { return m_roundTrips; }

private:
    bool ensureOpen();
    /// How many equal sub-steps the in-process law takes from its committed state to u.
    int subSteps(double u) const;
    bool request(const std::string& text, std::string& answer);
    /// Queue "param" for the named parameters whose value differs from what OpenSees has.
    void queueChangedParameters();
    /// m_uRef, m_fRef from the model (1 where it has none).
    void readScales();
    void fail(std::string why);

    std::string m_host;
    std::uint16_t m_port = 0;
    std::string m_element;
    std::unique_ptr<HysteresisLaw> m_model;
    OpenSeesTwinOptions m_options;
    OfSocket m_socket;
    bool m_opened = false, m_broken = false;
    std::string m_outbox; ///< requests without an answer, sent with the next trial
    std::string m_reason;
    std::vector<std::string> m_names;   ///< the model's parameter names
    std::vector<double> m_sent;         ///< per name: the value OpenSees has (NaN: local only)
    double m_uRef = 1.0, m_fRef = 1.0;
    double m_uTrial = 0.0, m_fTrial = 0.0, m_uCommitted = 0.0, m_fCommitted = 0.0;
    long m_roundTrips = 0;
};

} // namespace hsmu::comms::of
