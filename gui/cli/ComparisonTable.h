#pragma once
// ComparisonTable: the table `hsmu compare` prints on stdout: one row per run (initial,
// updated) with the compared element's force NRMSE [%] and peak error [force unit] and the
// compared DOF's displacement NRMSE [%] and peak error [m], all against the reference run,
// aligned in columns; with multi-DOF (link2d) elements a row per run and basic DOF
// (deformation and force NRMSE [%] and peak error [the DOF's unit]) and a row per run and
// actuator (its tracking J1 [ms], J2, J3 [%] against its command, its force NRMSE [%] and peak
// error [kN] against the reference run; core/session/ChannelComparison.h); then the updated
// run's final parameters (± std, and the true value where known).
// Thread rules: pure functions, any thread.

#include "core/session/ComparisonProtocol.h"
#include "core/identification/ParameterSet.h"

#include <QCoreApplication>
#include <QString>

namespace hsmu::gui {

class ComparisonTable {
    Q_DECLARE_TR_FUNCTIONS(ComparisonTable)
public:
    /// The whole text, lines ending in '\n'.
    static QString format(const ComparisonResult& result, const ParameterValues& truth);
    /// The per basic DOF and per actuator tables alone ("" without multi-DOF elements).
    static QString channelTables(const ComparisonResult& result);
};

} // namespace hsmu::gui
