#pragma once
// The reference run of an RTHS configuration with a damper (docs/rths.md, "A damper and its
// twin"): the reference structure with MR dampers on some storeys, so that J4..J9 of a run
// with a damper compare against the structure WITH the damper, not the bare one.

#include "core/groundmotion/GroundMotion.h"
#include "core/hysteresis/MrDamper.h"
#include "core/rths/DamperTwin.h"
#include "core/rths/Partition.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace hsmu::rths {

/// MR dampers of the reference structure: (DOF i, law) acts on storey i (between DOF i - 1 and
/// i; DOF 0: against the ground), deformation [m] -> force [N].
struct ReferenceDampers {
    std::vector<std::pair<int, MrDamperParameters>> storeys;
};

/// The dampers of the reference run: the damper in the specimen at the specimen's DOF, and at
/// the twin's storey the device the twin models, with the specimen's law (the truth the twin
/// is identified toward). None without a damper.
ReferenceDampers referenceDampers(const Partition& partition, const DamperSettings& damper);

/// The reference structure's response at the loop's ticks (RK4 at h, as the loop): row k,
/// column i = floor i's displacement [m] at t = k h, for ticks 0 .. n-1. The dampers' storey
/// forces are stepped once per tick at its start and held over it, as the loop does (operator
/// splitting); without dampers this is RthsLoop.h's referenceResponse, bit for bit.
Eigen::MatrixXd referenceResponse(const LinearStructure& reference, const GroundMotion& ag,
                                  double h, long n, const ReferenceDampers& dampers);

} // namespace hsmu::rths
