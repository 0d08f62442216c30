#include "core/updating/ModelUpdater.h"

#include "core/experimental/ExperimentalElement.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/OffsetLaw.h"
#include "core/structure/Structure.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsmu {

ModelUpdater::ModelUpdater(std::string specimenElement,
                           std::unique_ptr<HysteresisLaw> auxiliaryLaw,
                           std::unique_ptr<Identifier> identifier,
                           const InspectorSettings& inspector, std::unique_ptr<Reporter> reporter)
    : m_specimen(std::move(specimenElement)), m_aux(std::move(auxiliaryLaw)),
      m_auxInitial(m_aux->clone()), m_identifier(std::move(identifier)), m_inspector(inspector),
      m_reporter(std::move(reporter))
{
}

ModelUpdater::~ModelUpdater() = default;

bool ModelUpdater::attach(Structure& structure, double dt, std::string* error)
{
    Element* e = structure.element(m_specimen);
    m_element = e && e->isExperimental() ? static_cast<ExperimentalElement*>(e) : nullptr;
    if (!m_element) {
        if (error)
            *error = "updating: '" + m_specimen + "' is not an experimental element";
        return false;
    }
    if (m_basicDof >= m_element->basicDofCount()) {
        if (error)
            *error = "updating: basic DOF " + std::to_string(m_basicDof) + " of '" + m_specimen +
                     "' is out of range: a " + m_element->typeName() + " has " +
                     std::to_string(m_element->basicDofCount()) + " (0 .. " +
                     std::to_string(m_element->basicDofCount() - 1) + ")";
        return false;
    }
    const ParameterLayout& layout = m_identifier->layout();
    if (!m_reporter->bind(structure, layout, error))
        return false;
    m_auxIndex.clear();
    for (const auto& name : layout.names())
        m_auxIndex.push_back(m_aux->parameterIndex(name));
    m_inspector = Inspector(m_inspector.settings(), dt);
    m_dt = dt;
    m_aux->setTimeIncrement(dt);
    m_auxInitial->setTimeIncrement(dt);
    return true;
}

LawStatus ModelUpdater::stepAuxiliary(double deformation, bool first)
{
    // A rate-dependent model reaches the first sample quasi-statically, as every replay of a
    // measured history does (historyTimeIncrement): in a run it is one step from rest at 0.
    if (first)
        m_aux->setTimeIncrement(std::numeric_limits<double>::infinity());
    const LawStatus status = m_aux->setTrialDeformation(deformation);
    if (first)
        m_aux->setTimeIncrement(m_dt);
    if (status == LawStatus::Ok)
        m_aux->commit();
    return status;
}

void ModelUpdater::applyToAuxiliary(std::span<const double> values)
{
    m_auxApply.clear();
    m_auxValues.clear();
    for (std::size_t k = 0; k < values.size() && k < m_auxIndex.size(); ++k) {
        if (std::isfinite(values[k])) {
            m_auxApply.push_back(m_auxIndex[k]);
            m_auxValues.push_back(values[k]);
        }
    }
    // As one set first (beta and gamma may change sign together), value by value if refused.
    if (m_aux->setParameterValues(m_auxApply, m_auxValues, true) != -1)
        m_aux->setParameterValues(m_auxApply, m_auxValues, false);
}

void ModelUpdater::report(std::vector<UpdateEvent>& events, std::vector<Alarm>& alarms,
                          int step, double time, UpdatingSample& out)
{
    for (auto& ev : events) {
        if (ev.ok) {
            ++out.updatesThisStep;
            out.applied.push_back(std::move(ev));
        } else if (ev.decision == UpdateDecision::Rejected ||
                   ev.decision == UpdateDecision::Superseded) {
            out.decided.push_back(std::move(ev));
        } else if (ev.decision == UpdateDecision::NotQueued) {
            if (!m_queueFullReported)
                alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::ModelUpdate,
                                  "update not applied: " + ev.message +
                                      " (this and later offers are in the record until the "
                                      "operator decides)",
                                  "approval-queue-full",
                                  {std::to_string(m_reporter->maxPending())}});
            m_queueFullReported = true;
            out.decided.push_back(std::move(ev));
        } else
            alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::ModelUpdate,
                              "update not applied: " + ev.message});
    }
    if (static_cast<int>(m_reporter->pending().size()) < m_reporter->maxPending())
        m_queueFullReported = false;
}

std::optional<std::string> ModelUpdater::afterCommit(int step, double time, Structure& structure,
                                                     std::vector<Alarm>& alarms,
                                                     UpdatingSample& out)
{
    {
        // A fresh sample that keeps the vectors' storage (no allocation per step).
        std::vector<double> parameters = std::move(out.parameters);
        std::vector<double> stddev = std::move(out.stddev);
        out = UpdatingSample{};
        out.parameters = std::move(parameters);
        out.stddev = std::move(stddev);
    }
    const ControlMeasurement m = m_basicDof < 0 ? m_element->measurement()
                                                : m_element->basicMeasurement(m_basicDof);
    const double dm = m.deformation;
    const double fm = m.force;

    // Auxiliary model: the prediction with the parameters known before this step.
    if (stepAuxiliary(dm, m_history.empty()) != LawStatus::Ok)
        alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::EstimatorRejected,
                          "auxiliary model did not converge at deformation " + std::to_string(dm)});
    out.auxiliaryForce = m_aux->committedForce();
    m_history.push_back(dm);

    const IdentificationStatus st = m_identifier->observe(dm, fm, m_inspector.updateRequested());
    const std::span<const double> values = m_identifier->estimate();
    if (st.updated) {
        if (st.refit) {
            // A batch fit: replay the auxiliary model over the history with the new values.
            m_aux = m_auxInitial->clone();
            applyToAuxiliary(values);
            for (std::size_t k = 0; k < m_history.size(); ++k)
                stepAuxiliary(m_history[k], k == 0);
        } else {
            applyToAuxiliary(values);
        }
        if (!st.message.empty() && !st.modelInadequate)
            alarms.push_back({time, step, AlarmSeverity::Info, AlarmKind::ModelUpdate, st.message});
    }
    if (st.modelInadequate)
        alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::FitError, st.message});

    InspectorInput in;
    in.step = step;
    in.time = time;
    in.measuredForce = fm;
    in.auxiliaryForce = out.auxiliaryForce;
    in.measuredDeformation = dm;
    in.commandedDeformation = m_basicDof < 0 ? m_element->commandedDeformation()
                                             : m_element->commandedBasicDeformation(m_basicDof);
    in.estimatorOk = st.ok;
    in.estimatorMessage = st.message;
    in.parameters = &m_identifier->layout();
    in.parameterValues = values;
    in.parameterBounds = m_identifier->bounds();
    m_inspector.observe(in, alarms);

    if (st.updated && st.reportable) {
        m_events.clear();
        m_reporter->setProposalFitError(m_inspector.fitError());
        m_reporter->offer(step, time, values, structure, m_events);
        report(m_events, alarms, step, time, out); // counts the applied ones
    }
    if (m_offsets && m_offsets->observe(step, time, dm, fm)) {
        const OffsetProposal& p = *m_offsets->pending();
        const std::string u0 = std::to_string(p.deformationOffset);
        const std::string f0 = std::to_string(p.forceOffset);
        alarms.push_back({time, step, AlarmSeverity::Info, AlarmKind::ModelUpdate,
                          "offsets proposed for the twins: u0 = " + u0 + ", F0 = " + f0 +
                              " (they apply only when the operator approves them)",
                          "offsets-proposed", {u0, f0}});
    }
    if (m_autoResolve && !m_reporter->pending().empty()) {
        auto resolved = m_reporter->resolveAll(*m_autoResolve, structure, step, time);
        report(resolved, alarms, step, time, out);
    }

    out.fitError = m_inspector.fitError();
    out.tracking = m_inspector.tracking();
    out.updateRequested = m_inspector.updateRequested();
    fillEstimate(out);
    out.appliedUpdates = m_reporter->appliedCount();
    out.pendingProposals = static_cast<int>(m_reporter->pending().size());

    m_rejections = st.ok ? 0 : m_rejections + 1;
    if (m_rejections >= m_maxRejections) {
        m_rejections = 0;
        return "the " + m_identifier->methodName() + " rejected " +
               std::to_string(m_maxRejections) + " steps in a row (diverging estimator): " +
               st.message;
    }
    return std::nullopt;
}

void ModelUpdater::fillEstimate(UpdatingSample& out) const
{
    const std::span<const double> values = m_identifier->estimate();
    const std::span<const double> sd = m_identifier->standardDeviation();
    out.parameters.assign(values.begin(), values.end());
    out.stddev.assign(sd.begin(), sd.end());
}

bool ModelUpdater::approve(int proposalId, Structure& structure, int step, double time,
                           std::vector<Alarm>& alarms)
{
    auto ev = m_reporter->approve(proposalId, structure, step, time);
    if (!ev)
        return false;
    if (!ev->ok)
        alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::ModelUpdate,
                          "update not applied: " + ev->message});
    return ev->ok;
}

const OffsetProposal* ModelUpdater::pendingOffsets() const
{
    return m_offsets && m_offsets->pending() ? &*m_offsets->pending() : nullptr;
}

std::optional<OffsetProposal> ModelUpdater::approveOffsets(int id, Structure& structure,
                                                           std::string* error)
{
    const OffsetProposal* p = pendingOffsets();
    if (!p || p->id != id) {
        if (error)
            *error = "offsets #" + std::to_string(id) + " are not pending";
        return std::nullopt;
    }
    std::vector<std::pair<Element*, int>> targets; // (element, basic DOF)
    for (const ReporterTarget& t : m_reporter->targets()) {
        Element* e = structure.element(t.element);
        if (!reporterTargetLaw(e, t.basicDof)) {
            if (error)
                *error = "offsets not applied: target '" + t.element +
                         "' is not a numerical element with a law";
            return std::nullopt;
        }
        targets.emplace_back(e, t.basicDof);
    }
    for (auto [e, dof] : targets) {
        HysteresisLaw* current = reporterTargetLaw(e, dof);
        if (auto* law = dynamic_cast<OffsetLaw*>(current)) {
            const int idx[] = {law->parameterIndex(OffsetLaw::kDeformationOffset),
                               law->parameterIndex(OffsetLaw::kForceOffset)};
            const double values[] = {p->deformationOffset, p->forceOffset};
            law->setParameterValues(idx, values, true);
        } else {
            // The element's own law (its state, and an OpenSees twin its connection) goes
            // inside the offsets: a copy holds its place while it is taken out.
            std::unique_ptr<HysteresisLaw> own = current->clone();
            swapReporterTargetLaw(*e, dof, own); // own: the element's own law
            std::unique_ptr<HysteresisLaw> wrapped = std::make_unique<OffsetLaw>(
                std::move(own), p->deformationOffset, p->forceOffset);
            swapReporterTargetLaw(*e, dof, wrapped); // wrapped: the copy (released here)
        }
    }
    // The targets' laws changed objects: the reporter resolves them again.
    std::string bindError;
    if (!m_reporter->bind(structure, m_identifier->layout(), &bindError) && error)
        *error = bindError;
    return m_offsets->take(id);
}

std::optional<OffsetProposal> ModelUpdater::rejectOffsets(int id)
{
    return m_offsets ? m_offsets->take(id) : std::nullopt;
}

} // namespace hsmu
