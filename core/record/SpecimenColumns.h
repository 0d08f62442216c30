#pragma once
// SpecimenColumns: where a record (docs/recording.md) keeps the measured history of a
// specimen's identified DOF: the specimen's own columns (/elements deformation and force: a
// one-DOF specimen, a link2d's primary basic DOF) or, for a link2d's basic DOF named by
// /updating `basic_dof` (docs/configuration.md, updating.basicDof), its channels "<DOF>
// deformation" and "<DOF> force" of /elements/channels. Offline identification
// (core/offline/SpecimenHistory.h) and the robust UKF's seed record (updating.ukf.seedRecord)
// read it through here. Units: the columns' own (layout units).

#include "core/record/RecordData.h"

#include <string>

namespace hsmu {

struct SpecimenColumns {
    int element = -1;                 ///< the specimen's column in /elements
    int deformationChannel = -1;      ///< its basic DOF's channels (-1: its own columns)
    int forceChannel = -1;
    ElementUnits units;               ///< of the deformation and force read
    double deformation(const RecordData& r, int row) const;
    double force(const RecordData& r, int row) const;
};

/// The columns of experimental element `element` in `r`, of basic DOF `basicDof` ("axial",
/// "shear", "rotation"; "" for its own columns, or when `basicDof` is "" and the record's
/// /updating identified that specimen's basic DOF, that DOF's channels). Throws
/// std::invalid_argument (prefixed by `source`: when not empty) when there is no such specimen or channel.
SpecimenColumns specimenColumns(const RecordData& r, const std::string& element,
                                const std::string& source, std::string basicDof = {});

} // namespace hsmu
