#pragma once
// Drives one OpenFresco 2.8 experimental setup in the real OpenSees of ../shared/tools/opensees
// without a hybrid test: a zero-length `expElement twoNodeLink` (basic DOFs = node 2's
// displacements u, v, theta with node 1 fixed; -orient along global x, y) on a LocalSite with
// the setup and `expControl SimUniaxialMaterials`, node 2 imposed by sp constraints whose Path
// time series hold the basic-displacement history, one static step per row. Written per step:
// the element's ctrlDisp (trial basic displacements), daqDisp and daqForce (measured basic
// displacements and forces, through the setup), and the control's actuator ctrlDisp, daqDisp
// and daqForce (expRecorder Control, 17 digits). A free dummy node on a spring keeps the
// system non-empty. docs/setups.md, "Checked against OpenFresco".

#include "../../../comms/OpenSeesRunner.h"

#include <QString>
#include <QStringList>

#include <array>
#include <vector>

namespace ofsetup {

using Row = std::vector<double>;
using Table = std::vector<Row>;

struct Run {
    bool ran = false;                                   ///< every file has one row per step
    QString output;                                     ///< the interpreter's text (for messages)
    Table trial, basicDisp, basicForce;                 // element: ctrlDisp, daqDisp, daqForce
    Table actuatorCommand, actuatorDisp, actuatorForce; // control: ctrlDisp, daqDisp, daqForce
};

inline QString numbers(const std::vector<double>& v) {
    QStringList s;
    for (double x : v)
        s << QString::number(x, 'g', 17);
    return s.join(' ');
}

/// Path time series and sp patterns imposing node 2's DOFs 1..N from the history's rows, one
/// row per unit of pseudo-time (row k at time k + 1, rest at 0).
template <std::size_t N>
inline QStringList imposeHistory(const std::vector<std::array<double, N>>& history) {
    QStringList tcl;
    std::vector<double> times{0.0};
    for (std::size_t k = 1; k <= history.size(); ++k)
        times.push_back(static_cast<double>(k));
    for (std::size_t c = 0; c < N; ++c) {
        std::vector<double> values{0.0};
        for (const auto& row : history)
            values.push_back(row[c]);
        tcl << QString("timeSeries Path %1 -time {%2} -values {%3}")
                   .arg(c + 1)
                   .arg(numbers(times), numbers(values));
        tcl << QString("pattern Plain %1 %1 { sp 2 %1 1.0 }").arg(c + 1);
    }
    return tcl;
}

/// dir/name as a table; a control recorder (control = true) also writes the state at setup, an
/// extra first row that is dropped.
inline Table recorded(const QString& dir, const char* name, int n, bool control = false) {
    Table t = opensees::table(dir + "/" + name);
    if (control && static_cast<int>(t.size()) == n + 1)
        t.erase(t.begin());
    return t;
}

/// n static steps, each writing element 1's ctrlDisp, daqDisp and daqForce to ele_trial.out,
/// ele_disp.out and ele_force.out; then wipes (wipeExp first when asked: it ends a GenericTCP
/// session) and prints doneMark.
inline QStringList stepAndRecord(int n, const QString& doneMark, bool wipeExp = false) {
    QStringList tcl;
    tcl << "system BandGeneral"
        << "numberer Plain"
        << "constraints Transformation"
        << "algorithm Linear"
        << "integrator LoadControl 1.0"
        << "analysis Static"
        << "set ft [open ele_trial.out w]"
        << "set fd [open ele_disp.out w]"
        << "set ff [open ele_force.out w]" << QString("for {set k 0} {$k < %1} {incr k} {").arg(n)
        << "  if {[analyze 1] != 0} { puts \"ANALYZE FAILED\"; break }"
        << "  puts $ft [eleResponse 1 ctrlDisp]"
        << "  puts $fd [eleResponse 1 daqDisp]"
        << "  puts $ff [eleResponse 1 daqForce]"
        << "}"
        << "close $ft"
        << "close $fd"
        << "close $ff";
    if (wipeExp)
        tcl << "wipeExp";
    tcl << "wipe"
        << "puts " + doneMark;
    return tcl;
}

/// setupLine: the `expSetup ... 1 -control 1 ...` line (plus any sub-setups before it);
/// materials: `uniaxialMaterial` lines with tags 1..m, one per actuator in order.
inline Run run(const QString& dir, const QString& setupLine, const QStringList& materials,
               const std::vector<std::array<double, 3>>& history) {
    const int n = static_cast<int>(history.size());
    QStringList tcl;
    tcl << "model BasicBuilder -ndm 2 -ndf 3"
        << "loadPackage OpenFrescoTcl"
        << "node 1 0.0 0.0"
        << "node 2 0.0 0.0"
        << "node 3 0.0 0.0"
        << "fix 1 1 1 1";
    tcl << materials;
    QStringList tags;
    for (int i = 1; i <= materials.size(); ++i)
        tags << QString::number(i);
    tcl << "uniaxialMaterial Elastic 99 1.0"
        << "expControl SimUniaxialMaterials 1 " + tags.join(' ') << setupLine
        << "expSite LocalSite 1 1"
        << "expRecorder Control -file act_cmd.out -precision 17 -control 1 ctrlDisp"
        << "expRecorder Control -file act_disp.out -precision 17 -control 1 daqDisp"
        << "expRecorder Control -file act_force.out -precision 17 -control 1 daqForce"
        << "expElement twoNodeLink 1 1 2 -dir 1 2 3 -site 1 -initStif 1e6 0 0 0 1e6 0 0 0 1e6 "
           "-orient 1 0 0 0 1 0"
        << "element zeroLength 2 1 3 -mat 99 99 99 -dir 1 2 3";
    tcl << imposeHistory(history) << stepAndRecord(n, "SETUP_RUN_DONE");
    const opensees::Result r = opensees::run(dir, "setup.tcl", tcl.join('\n') + '\n', 60000);
    Run out;
    out.output = r.output;
    out.trial = recorded(dir, "ele_trial.out", n);
    out.basicDisp = recorded(dir, "ele_disp.out", n);
    out.basicForce = recorded(dir, "ele_force.out", n);
    out.actuatorCommand = recorded(dir, "act_cmd.out", n, true);
    out.actuatorDisp = recorded(dir, "act_disp.out", n, true);
    out.actuatorForce = recorded(dir, "act_force.out", n, true);
    out.ran = r.finished && r.output.contains("SETUP_RUN_DONE");
    for (const Table* t : {&out.trial, &out.basicDisp, &out.basicForce, &out.actuatorCommand,
                           &out.actuatorDisp, &out.actuatorForce})
        out.ran = out.ran && static_cast<int>(t->size()) == n;
    return out;
}

} // namespace ofsetup
