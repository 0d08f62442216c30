#include "core/record/RecordColumns.h"

#include <algorithm>
#include <optional>
#include <tuple>

namespace hsmu {

namespace {

using Matrix = Eigen::MatrixXd RecordData::*;

RecordColumn matrixColumn(std::string name, std::string unit, Matrix m, Eigen::Index j) {
    return {std::move(name), std::move(unit), false,
            [m, j](const RecordData& d, Eigen::Index i) { return (d.*m)(i, j); }};
}

RecordTable dofs(const RecordData& r) {
    RecordTable t{"dofs.csv", {}};
    const std::tuple<const char*, const char*, Matrix> kinds[] = {
        {"u", "m", &RecordData::u}, {"v", "m/s", &RecordData::v}, {"a", "m/s^2", &RecordData::a}};
    t.dofRows = !r.meta.dofRecording.full();
    const std::size_t kept = r.meta.dofRecording.dofs.empty() ? r.layout.dofNames.size()
                                                              : r.meta.dofRecording.dofs.size();
    for (const auto& [kind, unit, m] : kinds)
        for (std::size_t j = 0; j < kept; ++j) {
            const std::string& dof = r.layout.dofNames[std::size_t(r.dofIndex(int(j)))];
            t.columns.push_back(
                matrixColumn(std::string(kind) + " " + dof, unit, m, Eigen::Index(j)));
            t.columns.back().dofRows = t.dofRows;
        }
    return t;
}

RecordTable elements(const RecordData& r) {
    RecordTable t{"elements.csv", {}};
    for (std::size_t j = 0; j < r.layout.elements.size(); ++j) {
        const ElementInfo& e = r.layout.elements[j];
        const auto k = Eigen::Index(j);
        t.columns.push_back(matrixColumn(e.name + " deformation", e.units.deformation,
                                         &RecordData::deformation, k));
        t.columns.push_back(matrixColumn(e.name + " force", e.units.force, &RecordData::force, k));
        t.columns.push_back(
            matrixColumn(e.name + " commanded", e.units.deformation, &RecordData::commanded, k));
    }
    return t;
}

/// actuators.csv: the actuator channels of every specimen (records that have them).
std::optional<RecordTable> actuators(const RecordData& r) {
    const auto n = Eigen::Index(r.layout.elements.size());
    if (r.actuatorCommanded.rows() != r.rows() || r.actuatorCommanded.cols() != n ||
        std::none_of(r.layout.elements.begin(), r.layout.elements.end(),
                     [](const ElementInfo& e) { return e.experimental; }))
        return std::nullopt;
    RecordTable t{"actuators.csv", {}};
    for (std::size_t j = 0; j < r.layout.elements.size(); ++j) {
        const ElementInfo& e = r.layout.elements[j];
        if (!e.experimental)
            continue;
        const auto k = Eigen::Index(j);
        t.columns.push_back(matrixColumn(e.name + " actuator commanded", e.units.deformation,
                                         &RecordData::actuatorCommanded, k));
        t.columns.push_back(matrixColumn(e.name + " actuator measured", e.units.deformation,
                                         &RecordData::actuatorMeasured, k));
        t.columns.push_back(matrixColumn(e.name + " held ticks", "-", &RecordData::heldTicks, k));
        t.columns.push_back(matrixColumn(e.name + " flags", "-", &RecordData::actuatorFlags, k));
    }
    return t;
}

/// channels.csv: every basic DOF and actuator of the multi-DOF elements (records that have them).
std::optional<RecordTable> channels(const RecordData& r) {
    const auto n = Eigen::Index(r.layout.channels.size());
    if (n == 0 || r.channels.rows() != r.rows() || r.channels.cols() != n)
        return std::nullopt;
    RecordTable t{"channels.csv", {}};
    for (Eigen::Index j = 0; j < n; ++j) {
        const ElementChannel& c = r.layout.channels[std::size_t(j)];
        t.columns.push_back(matrixColumn(c.element + " " + c.name, c.unit, &RecordData::channels, j));
    }
    return t;
}

std::optional<RecordTable> sites(const RecordData& r) {
    const auto n = r.siteRoundTrip.cols();
    if (n == 0 || r.siteRoundTrip.rows() != r.rows())
        return std::nullopt;
    RecordTable t{"sites.csv", {}};
    for (Eigen::Index j = 0; j < n; ++j)
        t.columns.push_back(matrixColumn((std::size_t(j) < r.layout.sites.size()
                                              ? r.layout.sites[std::size_t(j)]
                                              : "site " + std::to_string(j + 1)) +
                                             " round trip",
                                         "s", &RecordData::siteRoundTrip, j));
    return t;
}

RecordColumn count(const char* name, const std::vector<int> RecordData::*v) {
    return {name, "-", true,
            [v](const RecordData& d, Eigen::Index i) { return double((d.*v)[std::size_t(i)]); }};
}

RecordTable updating(const RecordData& r) {
    const UpdatingInfo& info = *r.layout.updating;
    RecordTable t{"updating.csv", {}};
    for (std::size_t j = 0; j < info.parameters.size(); ++j)
        t.columns.push_back(
            matrixColumn(info.parameters[j], "-", &RecordData::parameters, Eigen::Index(j)));
    for (std::size_t j = 0; j < info.parameters.size(); ++j)
        t.columns.push_back(matrixColumn("stddev " + info.parameters[j], "-", &RecordData::stddev,
                                         Eigen::Index(j)));
    t.columns.push_back({"auxiliary_force", info.units.force, false,
                         [](const RecordData& d, Eigen::Index i) { return d.auxiliaryForce[i]; }});
    t.columns.push_back({"fit_error", "-", false,
                         [](const RecordData& d, Eigen::Index i) { return d.fitError[i]; }});
    t.columns.push_back(count("applied_updates", &RecordData::appliedUpdates));
    t.columns.push_back(count("updates_this_step", &RecordData::updatesThisStep));
    t.columns.push_back(count("pending_proposals", &RecordData::pendingProposals));
    if (r.tracking.rows() == r.rows() && r.rows() > 0) { // schema 2
        t.columns.push_back(matrixColumn("tracking_j1", "s", &RecordData::tracking, 0));
        t.columns.push_back(matrixColumn("tracking_j2", "-", &RecordData::tracking, 1));
        t.columns.push_back(matrixColumn("tracking_j3", "-", &RecordData::tracking, 2));
        t.columns.push_back(count("update_requested", &RecordData::updateRequested));
    }
    return t;
}

} // namespace

RecordColumn stepColumn() {
    return {"step", "", true,
            [](const RecordData& d, Eigen::Index i) { return double(d.steps[std::size_t(i)]); }};
}

RecordColumn timeColumn() {
    return {"time", "s", false, [](const RecordData& d, Eigen::Index i) { return d.time[i]; }};
}

RecordColumn dofStepColumn() {
    return {"step", "", true,
            [](const RecordData& d, Eigen::Index i) { return double(d.dofStep(int(i))); }, true};
}

RecordColumn dofTimeColumn() {
    return {"time", "s", false,
            [](const RecordData& d, Eigen::Index i) { return d.dofTime(int(i)); }, true};
}

std::vector<RecordTable> recordTables(const RecordData& r) {
    std::vector<RecordTable> tables;
    tables.push_back(
        {"steps.csv",
         {{"ground_acceleration", "m/s^2", false,
           [](const RecordData& d, Eigen::Index i) { return d.groundAcceleration[i]; }}}});
    tables.push_back(dofs(r));
    tables.push_back(elements(r));
    if (auto t = actuators(r))
        tables.push_back(std::move(*t));
    if (auto t = channels(r))
        tables.push_back(std::move(*t));
    if (auto t = sites(r))
        tables.push_back(std::move(*t));
    if (r.layout.updating)
        tables.push_back(updating(r));
    return tables;
}

} // namespace hsmu
