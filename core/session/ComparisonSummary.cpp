#include "core/session/ComparisonSummary.h"

#include "core/experimental/setup/SetupScript.h"
#include "core/output/RunSummary.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace hsmu {

namespace {

nlohmann::json number(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json metricJson(const ComparisonMetric& m, const ComparisonRun& run) {
    return {{"force_nrmse", number(m.forceNrmse)},
            {"force_peak_error", number(m.forcePeakError)},
            {"displacement_nrmse", number(m.displacementNrmse)},
            {"displacement_peak_error", number(m.displacementPeakError)},
            {"steps", run.steps},
            {"final_state", run.finalState}};
}

nlohmann::json lastOf(const std::vector<std::string>& names,
                      const std::vector<std::vector<double>>& history) {
    nlohmann::json out = nlohmann::json::object();
    if (history.empty())
        return out;
    const std::vector<double>& last = history.back();
    for (std::size_t i = 0; i < names.size(); ++i)
        out[names[i]] = i < last.size() ? number(last[i]) : nullptr;
    return out;
}

nlohmann::json basicDofsJson(const std::vector<BasicDofComparison>& dofs) {
    nlohmann::json out = nlohmann::json::array();
    for (const BasicDofComparison& b : dofs)
        out.push_back({{"element", b.element},
                       {"dof", b.dof},
                       {"deformation_unit", b.deformationUnit},
                       {"force_unit", b.forceUnit},
                       {"deformation_nrmse", number(b.deformationNrmse)},
                       {"deformation_peak_error", number(b.deformationPeakError)},
                       {"force_nrmse", number(b.forceNrmse)},
                       {"force_peak_error", number(b.forcePeakError)}});
    return out;
}

nlohmann::json actuatorsJson(const std::vector<ActuatorComparison>& actuators) {
    nlohmann::json out = nlohmann::json::array();
    for (const ActuatorComparison& a : actuators) {
        nlohmann::json j = {{"element", a.element},
                            {"actuator", a.actuator},
                            {"control", a.control},
                            {"command_unit", a.commandUnit},
                            {"force_unit", a.forceUnit},
                            {"tracking", trackingJson(a.tracking, a.commandUnit)}};
        if (a.compared) {
            j["force_nrmse"] = number(a.forceNrmse);
            j["force_peak_error"] = number(a.forcePeakError);
        }
        out.push_back(std::move(j));
    }
    return out;
}

/// A link2d updating specimen's identified basic DOF k: the material of the one actuator that
/// drives k alone at rest (a row of J = ds/dd equal to +-e_k, e.g. NoTransformation's and
/// OneActuator's; the identified laws are odd, so a sign does not change them), when it is the
/// model's law; nullptr otherwise (no such actuator, the lab simulates the specimen as a
/// whole, another law).
const MaterialSpec* link2dTrueLaw(const TestConfig& cfg) {
    const int k = cfg.updating.basicDof;
    for (const ElementSpec& e : cfg.elements) {
        if (e.name != cfg.updating.specimen || !e.link2d || k < 0 || e.link2d->wholeSpecimen)
            continue;
        SetupsByTag setups;
        std::string error;
        Eigen::MatrixXd j;
        if (!parseSetupScript(e.link2d->setupScript, setups, error) || setups.size() != 1 ||
            !setups.begin()->second->jacobian(Eigen::VectorXd::Zero(3), j).ok)
            return nullptr;
        for (int i = 0; i < j.rows() && std::size_t(i) < e.link2d->actuators.size(); ++i) {
            Eigen::VectorXd unit = Eigen::VectorXd::Zero(j.cols());
            unit[k] = j(i, k) < 0.0 ? -1.0 : 1.0;
            const MaterialSpec& m = e.link2d->actuators[std::size_t(i)].material;
            if ((j.row(i).transpose() - unit).cwiseAbs().maxCoeff() <= 1e-12 &&
                m.law == cfg.updating.model.law)
                return &m;
        }
    }
    return nullptr;
}

} // namespace

ParameterValues trueParameters(const TestConfig& cfg, const std::vector<std::string>& names) {
    ParameterValues out;
    if (const MaterialSpec* truth = link2dTrueLaw(cfg)) {
        for (const auto& name : names)
            if (auto it = truth->params.find(name); it != truth->params.end())
                out[name] = it->second;
        return out;
    }
    for (const ElementSpec& e : cfg.elements) {
        // Only a specimen whose true law is the identified model's law has comparable values
        // (a Bouc-Wen specimen identified as bilinear has no "true" bilinear k0).
        if (e.name != cfg.updating.specimen || !e.experimental ||
            e.specimen.trueMaterial.law != e.material.law)
            continue;
        for (const auto& name : names)
            if (auto it = e.specimen.trueMaterial.params.find(name);
                it != e.specimen.trueMaterial.params.end())
                out[name] = it->second;
    }
    return out;
}

nlohmann::json makeComparisonSummary(const ComparisonResult& r, const TestConfig& cfg) {
    const ComparisonRun& u = r.updated;
    nlohmann::json j;
    j["config"] = {{"name", cfg.name}, {"file", cfg.sourcePath}};
    j["element"] = r.element;
    j["dof"] = r.dof;
    j["force_unit"] = r.forceUnit;
    j["deformation_unit"] = r.deformationUnit;
    j["displacement_unit"] = "m";
    j["runs"] = {{"initial", metricJson(r.initialMetric, r.initial)},
                 {"updated", metricJson(r.updatedMetric, r.updated)}};
    j["reference"] = {{"steps", r.reference.steps}, {"final_state", r.reference.finalState}};
    for (const ComparisonRun* run : {&r.reference, &r.initial, &r.updated}) {
        nlohmann::json tracking = nlohmann::json::object();
        for (std::size_t i = 0; i < run->tracking.size(); ++i)
            tracking[run->tracking[i].first] = trackingJson(run->tracking[i].second, run->trackingUnits[i]);
        nlohmann::json& block = run == &r.reference ? j["reference"] : j["runs"][run->name];
        block["tracking"] = tracking;
        block["link_security"] = linkSecurityJson(run->sites, run->linkSecurity);
        if (!run->channels.layout.empty()) { // multi-DOF elements: per basic DOF and actuator
            if (run != &r.reference)
                block["basic_dofs"] = basicDofsJson(run->basicDofs);
            block["actuators"] = actuatorsJson(run->actuators);
        }
    }
    j["parameters"] = u.parameterNames;
    j["final_parameters"] = lastOf(u.parameterNames, u.parameters);
    j["final_standard_deviations"] = lastOf(u.parameterNames, u.stddev);
    nlohmann::json truth = nlohmann::json::object();
    for (const auto& [name, value] : trueParameters(cfg, u.parameterNames))
        truth[name] = number(value);
    j["true_parameters"] = truth;
    j["applied_updates"] = u.appliedUpdates;
    j["steps"] = u.steps;
    j["alarms"] = {{"reference", r.reference.alarms},
                   {"initial", r.initial.alarms},
                   {"updated", r.updated.alarms}};
    return j;
}

void writeComparisonJson(const std::string& path, const ComparisonResult& result,
                         const TestConfig& cfg) {
    std::ofstream out(path, std::ios::out | std::ios::trunc);
    if (!out)
        throw std::runtime_error(path + ": cannot be opened for writing");
    out << makeComparisonSummary(result, cfg).dump(2) << '\n';
    out.flush();
    if (!out)
        throw std::runtime_error(path + ": write failed");
}

} // namespace hsmu
