#pragma once
// The SDOF of the OpenSees pairing tests and benchmark, written here (not copied from
// ../shared): mass 1 t on node 2, node 1 fixed, a Bouc-Wen spring (OpenSees order: alpha ko n
// gamma beta Ao deltaA deltaNu deltaEta) between them, El Centro N-S (g, 0.02 s) as uniform
// excitation, mass-proportional damping. The spring is either OpenSees' own zeroLength (the
// reference) or an element whose force comes over the network, served by hsmu-controller
// with the same law (controllerConfig()).

#include <nlohmann/json.hpp>

#include <QString>

namespace sdof {

inline const char* kBoucWenArgs = "0.05 40.0 1.5 100.0 300.0 1.0 0.0 0.2 0.2 1.0e-12 50";

/// The hsmu configuration with the same spring as the specimen ("Spring", a lateral spring on
/// the one DOF): served by hsmu-controller; dt as in the Tcl model.
inline nlohmann::json controllerConfig(double dt = 0.01) {
    const nlohmann::json law = {
        {"law", "boucWen"}, {"k0", 40.0}, {"alpha", 0.05}, {"n", 1.5},       {"gamma", 100.0},
        {"beta", 300.0},    {"A0", 1.0},  {"deltaA", 0.0}, {"deltaNu", 0.2}, {"deltaEta", 0.2}};
    return {{"structure",
             {{"dofs", {{{"name", "DOF 1"}, {"mass", 1.0}}}},
              {"elements",
               {{{"name", "Spring"},
                 {"type", "lateralSpring"},
                 {"dof", "DOF 1"},
                 {"material", law},
                 {"experimental", true},
                 {"specimen", {{"material", law}}}}}}}},
            {"analysis", {{"dt", dt}}}};
}

struct Options {
    QString element; ///< the spring's Tcl line(s), tag 1
    QString outDir;  ///< recorder folder
    double dt = 0.01;
    int steps = 200;
    QString integrator = "NewmarkExplicit 0.5";
    QString algorithm = "Linear";
    QString groundMotion;    ///< one column in g at 0.02 s
    bool openFresco = false; ///< loadPackage OpenFrescoTcl
    QString extra;           ///< lines after the element (expControl ...)
};

/// The model with `element` as the spring; recorders disp.out (node 2) and force.out (ele 1).
inline QString script(const Options& o) {
    QString s;
    s += "wipe\nmodel BasicBuilder -ndm 1 -ndf 1\n";
    if (o.openFresco)
        s += "loadPackage OpenFrescoTcl\n";
    s += "node 1 0.0\nnode 2 0.0 -mass 1.0\nfix 1 1\n";
    s += o.extra;
    s += o.element + "\n";
    s += QString("timeSeries Path 1 -dt 0.02 -filePath {%1} -factor 9.80665\n").arg(o.groundMotion);
    s += "pattern UniformExcitation 1 1 -accel 1\nrayleigh 0.25298221281347039 0 0 0\n";
    s += QString("recorder Node -precision 16 -file {%1/disp.out} -time -node 2 -dof 1 disp\n")
             .arg(o.outDir);
    s += QString("recorder Element -precision 16 -file {%1/force.out} -time -ele 1 force\n")
             .arg(o.outDir);
    s += "constraints Plain\nnumberer Plain\nsystem FullGeneral\n";
    s += "algorithm " + o.algorithm + "\nintegrator " + o.integrator + "\nanalysis Transient\n";
    s += QString("set t0 [clock microseconds]\nset ok [analyze %1 %2]\n").arg(o.steps).arg(o.dt);
    s += "puts \"analyze -> $ok, [expr {[clock microseconds] - $t0}] us\"\n";
    if (o.openFresco)
        s += "wipeExp\n";
    s += "wipe\n";
    return s;
}

/// The reference spring: OpenSees' zeroLength with uniaxialMaterial BoucWen.
inline QString zeroLength() {
    return QString("uniaxialMaterial BoucWen 1 %1\nelement zeroLength 1 1 2 -mat 1 -dir 1")
        .arg(kBoucWenArgs);
}

} // namespace sdof
