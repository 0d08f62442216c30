#include "core/updating/ModelUpdater.h"

#include "core/experimental/ExperimentalElement.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/structure/Structure.h"

#include <cmath>

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
    for (const auto& t : m_reporter->targets()) {
        Element* target = structure.element(t.element);
        if (!target || !target->law()) {
            if (error)
                *error = "updating: target '" + t.element + "' is not a numerical element with a law";
            return false;
        }
    }
    m_inspector = Inspector(m_inspector.settings(), dt);
    return true;
}

void ModelUpdater::applyToAuxiliary(const ParameterValues& values)
{
    for (const auto& [name, v] : values)
        if (std::isfinite(v))
            m_aux->setParameter(name, v);
}

void ModelUpdater::report(const std::vector<UpdateEvent>& events, std::vector<Alarm>& alarms,
                          int step, double time, UpdatingSample& out)
{
    for (const auto& ev : events) {
        if (ev.ok) {
            ++out.updatesThisStep;
            out.applied.push_back(ev);
        } else
            alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::ModelUpdate,
                              "update not applied: " + ev.message});
    }
}

std::optional<std::string> ModelUpdater::afterCommit(int step, double time, Structure& structure,
                                                     std::vector<Alarm>& alarms,
                                                     UpdatingSample& out)
{
    out = UpdatingSample{};
    const ControlMeasurement& m = m_element->measurement();
    const double dm = m.deformation;
    const double fm = m.force;

    // Auxiliary model: the prediction with the parameters known before this step.
    if (m_aux->setTrialDeformation(dm) == LawStatus::Ok)
        m_aux->commit();
    else
        alarms.push_back({time, step, AlarmSeverity::Warning, AlarmKind::EstimatorRejected,
                          "auxiliary model did not converge at deformation " + std::to_string(dm)});
    out.auxiliaryForce = m_aux->committedForce();
    m_history.push_back(dm);

    const IdentificationStatus st = m_identifier->observe(dm, fm, m_inspector.updateRequested());
    const ParameterValues estimate = m_identifier->estimate();
    if (st.updated) {
        if (st.refit) {
            // A batch fit: replay the auxiliary model over the history with the new values.
            m_aux = m_auxInitial->clone();
            applyToAuxiliary(estimate);
            for (double d : m_history)
                if (m_aux->setTrialDeformation(d) == LawStatus::Ok)
                    m_aux->commit();
        } else {
            applyToAuxiliary(estimate);
        }
        if (!st.message.empty())
            alarms.push_back({time, step, AlarmSeverity::Info, AlarmKind::ModelUpdate, st.message});
    }

    InspectorInput in;
    in.step = step;
    in.time = time;
    in.measuredForce = fm;
    in.auxiliaryForce = out.auxiliaryForce;
    in.measuredDeformation = dm;
    in.commandedDeformation = m_element->commandedDeformation();
    in.estimatorOk = st.ok;
    in.estimatorMessage = st.message;
    in.parameters = &estimate;
    in.bounds = &m_identifier->bounds();
    m_inspector.observe(in, alarms);

    if (st.updated)
        report(m_reporter->offer(step, time, estimate, structure), alarms, step, time, out);
    if (m_autoResolve && !m_reporter->pending().empty())
        report(m_reporter->resolveAll(*m_autoResolve, structure, step, time), alarms, step, time,
               out);

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
    const ParameterValues estimate = m_identifier->estimate();
    const ParameterValues sd = m_identifier->standardDeviation();
    out.parameters.clear();
    out.stddev.clear();
    for (const auto& name : m_identifier->parameterNames()) {
        auto e = estimate.find(name);
        auto s = sd.find(name);
        out.parameters.push_back(e == estimate.end() ? NAN : e->second);
        out.stddev.push_back(s == sd.end() ? 0.0 : s->second);
    }
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

} // namespace hsmu
