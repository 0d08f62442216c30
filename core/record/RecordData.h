#pragma once
// RecordData: the content of a run record (docs/recording.md) as RecordReader returns it.
// Row i of every per-step array is the committed step steps[i] (row 0: the initial state);
// N = rows(). Matrices are N x nDof / N x nElem / N x nParam, columns in `layout` order.
// Units: those of the structure (presets: m, s, kN, rad, kN m); element units per column in
// layout.elements[j].units; identified parameters in the law's own units (normalized by
// uRef / fRef for Bouc-Wen).

#include "core/output/DofRecording.h"
#include "core/output/RunLayout.h"
#include "core/util/Alarm.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hsmu {

struct RecordMetadata {
    int schemaVersion = 0;
    std::string program;        ///< "HSMU Console"
    std::string programVersion; ///< hsmu::versionString() of the writer
    std::string startTime;      ///< ISO 8601 UTC, e.g. "2024-05-01T12:00:00Z"
    std::string configuration;  ///< the configuration document as JSON text
    std::string configName;     ///< TestConfig::name
    std::string operatorNotes;
    double dt = 0.0; ///< integration step [s]
    std::string run; ///< schema 2: "reference", "initial", "updated" (hsmu compare) or ""
    /// How the writer evaluated the UKF's sigma points, e.g. "UKF sigma points: libmvec AVX2
    /// vector pow" (BoucWen::fastBatchMathName()); "" in records written before it was kept.
    std::string numerics;
    /// /sites' `security`, one per layout.sites ("tls", "plaintext-loopback",
    /// "insecure-plaintext", "builtin"); empty in records written before it was kept.
    std::vector<std::string> siteSecurity;
    /// /dofs' `dof_indices` and `every` (docs/recording.md "Chosen and decimated DOFs"): the
    /// DOFs the columns of u, v, a are and the stride of their rows; full() in a record of
    /// every DOF at every step (the default, and every record written before the option).
    DofRecording dofRecording;
};

/// A parameter update applied to a target element (/updating/events).
struct RecordedUpdate {
    int step = 0;
    double time = 0.0; ///< [s]
    std::string element;
    std::vector<double> values; ///< [nParam] in layout.updating order; NaN: not sent
    /// What became of the offer (UpdateDecision's code name: "applied", "refused", "rejected",
    /// "notQueued"); "applied" in records written before the column existed.
    std::string decision = "applied";
    int proposal = 0; ///< the approval proposal's id (0: none)
};

/// An operator note added during the run (/notes).
struct RecordNote {
    double time = 0.0; ///< test time [s]
    int step = 0;
    std::string text;
};

struct RecordData {
    RecordMetadata meta;
    RunLayout layout; ///< names, types, units; layout.updating set when updating ran

    std::vector<int> steps;             ///< [N] step index
    Eigen::VectorXd time;               ///< [N] [s]
    Eigen::VectorXd groundAcceleration; ///< [N] [m/s^2]
    /// [Nd x nKept] [m], [m/s], [m/s^2]: the numerical DOFs' matrices. Column j is DOF
    /// dofIndex(j) (every DOF, in layout.dofNames order, unless meta.dofRecording chose some);
    /// row k is step dofStep(k) (Nd = N unless decimated: then the steps that are multiples
    /// of meta.dofRecording.every).
    Eigen::MatrixXd u, v, a;
    /// [Nd] the step and test time [s] of each row of u, v, a when the record chose or
    /// decimated its DOFs (/dofs/step, /dofs/time); empty otherwise (those of steps, time).
    std::vector<int> dofSteps;
    Eigen::VectorXd dofTimes;
    Eigen::MatrixXd deformation;        ///< [N x nElem] element units (measured for specimens)
    Eigen::MatrixXd force;              ///< [N x nElem] element units (measured for specimens)
    Eigen::MatrixXd commanded;          ///< [N x nElem] NaN for numerical elements
    /// [N x nSite] each step's round trip per site [s] (layout.sites order; row 0 NaN); empty
    /// in records without /sites (no experimental element, or written before sites)
    Eigen::MatrixXd siteRoundTrip;
    // Actuator channels (/elements/actuator; 0 x 0 in records written before them): as each
    // specimen's control reported them with the step's measurement, NaN where it has none.
    Eigen::MatrixXd actuatorCommanded; ///< [N x nElem] element deformation units
    Eigen::MatrixXd actuatorMeasured;  ///< [N x nElem] element deformation units
    Eigen::MatrixXd heldTicks;         ///< [N x nElem] controller ticks held for a late target
    Eigen::MatrixXd actuatorFlags;     ///< [N x nElem] bit 0 fractured, bit 1 replayed
    /// [N x nChannel] the multi-DOF elements' channels (/elements/channels: every basic DOF
    /// and actuator, layout.channels order and units); 0 x 0 without them.
    Eigen::MatrixXd channels;

    // Online model updating (empty unless layout.updating).
    Eigen::MatrixXd parameters;        ///< [N x nParam] estimate
    Eigen::MatrixXd stddev;            ///< [N x nParam] standard deviations (0: none)
    Eigen::VectorXd auxiliaryForce;    ///< [N] specimen force units
    Eigen::VectorXd fitError;          ///< [N] inspector's normalized RMS error [-]
    std::vector<int> appliedUpdates;   ///< [N] cumulative updates applied to targets
    std::vector<int> updatesThisStep;  ///< [N]
    std::vector<int> pendingProposals; ///< [N]
    // Schema 2 (empty when reading a schema-1 file).
    Eigen::MatrixXd tracking;                 ///< [N x 3] J1 [s], J2 [-], J3 [-]
    std::vector<int> updateRequested;         ///< [N] 1: fit error above the threshold
    std::vector<RecordedUpdate> updateEvents; ///< in the order applied

    std::vector<RecordNote> notes; ///< schema 2; in the order added

    std::vector<Alarm> alarms; ///< in the order raised

    int rows() const { return int(steps.size()); }

    // The numerical DOFs' rows and columns (docs/recording.md "Chosen and decimated DOFs").
    int dofRows() const { return dofSteps.empty() ? rows() : int(dofSteps.size()); }
    int dofStep(int k) const {
        return dofSteps.empty() ? steps[std::size_t(k)] : dofSteps[std::size_t(k)];
    }
    double dofTime(int k) const { return dofSteps.empty() ? time(k) : dofTimes(k); }
    /// The DOF (index into layout.dofNames) of column j of u, v, a.
    int dofIndex(int j) const {
        const auto& kept = meta.dofRecording.dofs;
        return kept.empty() ? j : kept[std::size_t(j)];
    }
    /// The column of u, v, a holding DOF `dof`; -1 when the record did not keep it.
    int dofColumn(int dof) const;
    /// The row of u, v, a holding the step of row `row` (of steps); -1 when decimated away.
    int dofRowOf(int row) const;
    /// Why DOF `dof` has no column: "DOF 'NAME' (index I) was not recorded: the run kept DOFs
    /// LIST every N steps (hsmu run --record-dofs / --record-every, the configuration's
    /// record.dofs / record.every)".
    std::string dofNotRecorded(int dof) const;
};

} // namespace hsmu
