#pragma once
// InputLimits: the sane maxima every input is checked against *before* anything is allocated
// from it (docs/configuration.md, "Limits on inputs"). A value past one is an error naming the
// file and the field, never a std::bad_alloc or a run that silently does nothing.

#include <cstdint>

namespace hsmu::limits {

/// Integration steps of one run (10 million: 2.8 h of test at dt = 0.001 s).
inline constexpr std::int64_t kMaxSteps = 10'000'000;
/// Smallest and largest integration step / ground-motion step [s].
inline constexpr double kMinDt = 1e-6;
inline constexpr double kMaxDt = 10.0;
/// Longest analysis duration [s] (one day).
inline constexpr double kMaxDuration = 86'400.0;
/// Longest actuator delay and lag time constant [s].
inline constexpr double kMaxActuatorDelay = 1.0;
inline constexpr double kMaxActuatorTimeConstant = 10.0;
/// Deepest nesting of arrays and objects in a JSON configuration (a real one nests < 10;
/// deeper input could overflow a recursive walk's stack).
inline constexpr int kMaxJsonDepth = 64;
/// Largest ground-motion or CSV file read [bytes] (64 MiB).
inline constexpr std::uint64_t kMaxTextFileBytes = 64ull << 20;

} // namespace hsmu::limits
