#pragma once
// RecordCsvExport: a run record (RecordData, docs/recording.md) as CSV files, one per dataset
// group, for tools that do not read HDF5 (`hsmu export FILE.h5 --csv DIR`, docs/cli.md).
//
//   steps.csv          step, time [s], ground_acceleration [m/s^2]
//   dofs.csv           step, time [s], u <dof> [m] ..., v <dof> [m/s] ..., a <dof> [m/s^2] ...
//                      (the DOFs recorded; a record of chosen or decimated DOFs: one row per
//                      step kept, with its true step and time)
//   elements.csv       step, time [s], then per element: <name> deformation [unit],
//                      <name> force [unit], <name> commanded [unit]
//   actuators.csv      step, time [s], then per specimen: <name> actuator commanded [unit],
//                      <name> actuator measured [unit], <name> held ticks [-], <name> flags [-]
//                      (records with /elements/actuator and a specimen; nan: no channel)
//   channels.csv       step, time [s], then per channel of a multi-DOF element: <element>
//                      <channel> [unit] (every basic DOF's commanded, deformation, force and
//                      every actuator's command, stroke, force; records with /elements/channels)
//   updating.csv       step, time [s], <parameter> [-] ..., stddev <parameter> [-] ...,
//                      auxiliary_force [unit], fit_error [-], applied_updates [-],
//                      updates_this_step [-], pending_proposals [-] and, from schema 2,
//                      tracking_j1 [s], tracking_j2 [-], tracking_j3 [-], update_requested [-]
//                      (only when the run used online model updating)
//   update_events.csv  step, time [s], element, <parameter> [-] ...  (with updating)
//   alarms.csv         time [s], step, severity, kind, message
//   notes.csv          time [s], step, text
//
// The header line names each column with its unit in brackets ("[-]": dimensionless or the
// law's normalized units), as `hsmu replay --import` reads it. Numbers are written in the
// shortest form that reads back to the same double (std::to_chars, '.' whatever the locale);
// NaN is "nan". Text fields are quoted when they hold a comma, a quote or a line break.
// ExportUnits (`hsmu export --units`, docs/units.md) write the columns in lab units instead:
// lengths, forces, rotations, moments and times in the units named (core/util/Units.h),
// velocities and accelerations in length / time and length / time^2, moments by default in
// force x length; each header names the unit written.
// Thread rules: none.

#include <string>
#include <vector>

namespace hsmu {

struct RecordData;

/// Output units (Units.h symbols); an empty field: the console's unit (moment: force x length
/// when force or length is given, else kN m).
struct ExportUnits {
    std::string length, force, rotation, moment, time;
};

/// Parse "length=in,force=kip,rotation=deg,moment=kip*in,time=ms" (any subset). Throws
/// std::invalid_argument naming the pair or the unit and listing the accepted ones.
ExportUnits parseExportUnits(const std::string& text);

/// Writes the files above into the existing directory `dir` (overwriting). Returns the paths
/// written. Throws std::runtime_error naming a file that cannot be written. `units` must hold
/// units parseExportUnits accepts.
std::vector<std::string> exportRecordCsv(const RecordData& record, const std::string& dir,
                                         const ExportUnits& units = {});

} // namespace hsmu
