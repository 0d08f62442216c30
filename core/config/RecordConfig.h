#pragma once
// RecordConfig: the configuration's "record" block (docs/configuration.md "record"; issue 27):
//   "record": { "dofs": "0-99,Roof" | [0, "5-9", "Roof"], "every": 10 }
// the numerical DOFs the run record keeps in /dofs/u, v, a and the stride of their rows
// (core/output/DofRecording.h, docs/recording.md "Chosen and decimated DOFs"). Absent: every
// DOF at every step. A specimen's channels are always recorded in full at every step: keys
// that would choose or decimate them ("elements", "specimens", "channels", "actuators",
// "updating", "alarms") and a specimen's name in "dofs" are refused with that reason.
// `hsmu run --record-dofs LIST --record-every N` override the block through
// configDofList (the same parser). Thread rules: none.

#include "core/config/JsonCursor.h"
#include "core/output/DofRecording.h"

#include <string>
#include <vector>

namespace hsmu {

struct TestConfig;

/// The "record" block of `root` (cfg's DOFs and elements already parsed). Throws ConfigError
/// naming the field ("record.dofs: no DOF named 'X' ...").
DofRecording parseRecordSection(const JsonCursor& root, const TestConfig& cfg);

/// parseDofList against cfg's DOF names and experimental elements (throws
/// std::invalid_argument with the reason).
std::vector<int> configDofList(const TestConfig& cfg, const std::string& list);

/// The largest `every` accepted (record.every, --record-every).
inline constexpr int kMaxRecordEvery = 1000000;

} // namespace hsmu
