#pragma once
// RecordColumns: the per-step datasets of a run record (RecordData, docs/recording.md) as
// named columns with their console units, grouped in the tables `hsmu export --csv` writes
// (core/record/RecordCsvExport.h) and read one by one by the Python module's hsmu.Record
// (python/PyRecord, docs/python.md): the one list of names, units and values for both.
//
//   steps.csv      ground_acceleration [m/s^2]
//   dofs.csv       u <dof> [m] ..., v <dof> [m/s] ..., a <dof> [m/s^2] ... (the DOFs the
//                  record kept; a record that chose or decimated its DOFs has its own rows:
//                  RecordTable::dofRows, docs/recording.md "Chosen and decimated DOFs")
//   elements.csv   per element: <name> deformation, <name> force, <name> commanded [its units]
//   actuators.csv  per specimen: <name> actuator commanded, <name> actuator measured [its
//                  deformation unit], <name> held ticks [-], <name> flags [-] (records with
//                  /elements/actuator and a specimen)
//   channels.csv   per multi-DOF element channel: <element> <channel> [its unit], e.g.
//                  "Column L shear force" [kN], "Column L vertical stroke" [m] (records with
//                  /elements/channels; core/experiment/ElementChannels.h)
//   sites.csv      <site> round trip [s] (records with /sites/round_trip)
//   updating.csv   <parameter> [-] ..., stddev <parameter> [-] ..., auxiliary_force [force],
//                  fit_error [-], applied_updates, updates_this_step, pending_proposals [-],
//                  and from schema 2 tracking_j1 [s], tracking_j2, tracking_j3,
//                  update_requested [-] (runs with online model updating)
// Every table starts with step and time [s] (stepColumn, timeColumn), not repeated in
// RecordTable::columns. Units are the console's: "m", "m/s", "m/s^2", "rad", "kN", "kN m",
// "s"; "-" dimensionless or the law's normalized units; "" a step number.
// Thread rules: none (functions of the data).

#include "core/record/RecordData.h"

#include <functional>
#include <string>
#include <vector>

namespace hsmu {

struct RecordColumn {
    std::string name;     ///< as the CSV header names it, without the unit
    std::string unit;     ///< the console unit (above)
    bool integer = false; ///< a whole number (written without a decimal point)
    /// The value at row i (0 <= i < RecordData::rows(), or < dofRows() with dofRows).
    std::function<double(const RecordData&, Eigen::Index i)> value;
    /// A column of a record's chosen or decimated DOFs: its rows are RecordData's DOF rows
    /// (steps dofStep(i)), not every step.
    bool dofRows = false;
};

struct RecordTable {
    std::string file;                  ///< "steps.csv", "dofs.csv", ...
    std::vector<RecordColumn> columns; ///< after step and time
    bool dofRows = false;              ///< its rows are the DOF rows (dofStepColumn, dofTimeColumn)
};

/// "step" ("", integer) and "time" [s].
RecordColumn stepColumn();
RecordColumn timeColumn();
/// The same for the rows of a record's chosen or decimated DOFs (dofStep(i), dofTime(i)).
RecordColumn dofStepColumn();
RecordColumn dofTimeColumn();

/// The tables above that the record has, in that order.
std::vector<RecordTable> recordTables(const RecordData& r);

} // namespace hsmu
