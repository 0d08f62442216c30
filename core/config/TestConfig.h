#pragma once
// TestConfig: a hybrid test as the configuration file describes it (docs/configuration.md),
// parsed but not yet built. Plain data; ConfigLoader fills it, TestFactory builds from it.
// Units: kN, m, s, t (tonne) throughout; rotations in rad, moments in kN m.

#include "core/config/LinkConfig.h"
#include "core/config/SiteConfig.h"
#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/SafetyLimits.h"
#include "core/experimental/VirtualSpecimen.h"
#include "core/updating/Inspector.h"
#include "core/identification/ParameterSet.h"
#include "core/updating/Reporter.h"

#include <nlohmann/json.hpp>

#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

enum class Link2dTransformation; // core/structure/Link2dKinematics.h

struct MaterialSpec {
    std::string law = "elastic";          ///< "boucWen", "bilinear", "elastic"
    std::map<std::string, double> params; ///< law parameters by name
};

struct SpecimenSpec {
    MaterialSpec trueMaterial;       ///< the virtual specimen's own law
    VirtualSpecimenOptions options;  ///< noise, actuator, fracture, interlock
};

/// One basic DOF of a link2d element (docs/configuration.md, "link2d"): a law, or a held force.
struct Link2dBasicSpec {
    bool hasMaterial = false;
    MaterialSpec material;  ///< when hasMaterial
    double heldForce = 0.0; ///< [kN] or [kN m] otherwise (0: a free DOF)
    ForceSchedule forceSchedule; ///< (t [s], F) points instead of heldForce (eq. F1)
};

/// One actuator of a link2d specimen: its channel (control mode, held force, limits, K0), the
/// uniaxial material the in-process virtual lab simulates it with (none when the lab simulates
/// the whole specimen) and how it tracks its command (ActuatorTracker.h).
struct ActuatorSpec {
    ActuatorChannelSpec channel;
    MaterialSpec material; ///< unused with a WholeSpecimenSpec
    ActuatorModel model;   ///< "actuator": ideal, lag, delay, servoHydraulic
};

/// A link2d specimen simulated as a whole in its basic system by the virtual lab
/// (type "cantileverColumn", CantileverColumn.h; docs/setups.md "The specimen as a whole").
struct WholeSpecimenSpec {
    MaterialSpec hinge; ///< moment [kN m] - rotation [rad] law at the base
    MaterialSpec axial; ///< axial force [kN] - deformation [m] law
    double ei = 0.0;    ///< [kN m^2] the column above the hinge
};

/// A two-node 2D link / beam-column (type "link2d"; core/structure/Link2dKinematics.h).
struct Link2dSpec {
    std::array<int, 6> dofs{-1, -1, -1, -1, -1, -1}; ///< node i (x, y, theta), node j; -1: support
    double length = 0.0;                              ///< [m]
    double angle = 90.0;                              ///< [deg] of i -> j from x
    /// "geometry": linear (eq. L1) or corotational (eq. L3, large displacements)
    Link2dTransformation transformation{}; // Linear
    std::array<Link2dBasicSpec, 3> basic;             ///< axial, shear, rotation
    int primary = 1;                                  ///< the basic DOF the record reports
    std::string setupScript; ///< experimental: one OpenFresco expSetup line (SetupScript.h)
    std::vector<ActuatorSpec> actuators; ///< experimental: one per setup actuator
    /// experimental: the virtual lab simulates the specimen as a whole (else one material per
    /// actuator).
    std::optional<WholeSpecimenSpec> wholeSpecimen;
};

struct ElementSpec {
    std::string name;
    /// "lateralSpring" (dofs[0]), "truss" (dofs[0] -> dofs[1]),
    /// "rotationalBaseSpring" (dofs[0], height, optional ei for an elastic column)
    std::string type;
    std::vector<int> dofs;                                      ///< full-DOF indices
    double height = 0.0;                                        ///< column height [m]
    double ei = std::numeric_limits<double>::infinity();        ///< column EI [kN m^2]; inf = rigid
    MaterialSpec material;       ///< numerical model (for a specimen: its initial model)
    bool experimental = false;
    SpecimenSpec specimen;       ///< when experimental
    SafetyLimits limits;         ///< when experimental
    /// A numerical element whose force another program computes: "opensees://HOST:PORT" (an
    /// OpenSees twin, docs/opensees-twins.md); "" = in process.
    std::string numericalSite;
    /// The site serving it (a name from "sites"); "": the default site kDefaultSiteName.
    std::string site;
    /// type "link2d": its geometry, basic DOFs, setup and actuators.
    std::optional<Link2dSpec> link2d;
};

struct DofSpec {
    std::string name;
    double mass = 0.0; ///< [t] ([t m^2] on a rotational DOF)
    double influence = 1.0; ///< ground-motion influence iota (0: a rotation, docs/configuration.md)
};

struct DampingSpec {
    enum class Kind { None, ModalRatio, Coefficients };
    Kind kind = Kind::None;
    double ratio = 0.0;     ///< for ModalRatio
    int modeI = 1, modeJ = 2;
    double a0 = 0.0, a1 = 0.0; ///< for Coefficients
};

struct GroundMotionSpec {
    std::string builtin = "synthetic"; ///< used when file is empty
    std::string file;                  ///< path (relative to the configuration's folder)
    std::string format = "auto";       ///< auto, at2, time-acc, single
    std::string units;                 ///< g, m/s^2, cm/s^2 ("" = from the file / g)
    double dt = 0.0;                   ///< for single-column files [s]
    double scale = 1.0;
    unsigned seed = 1940;              ///< for the synthetic record
};

struct AnalysisSpec {
    std::string integrator = "explicitNewmark"; ///< or "alphaOS"
    double alpha = -0.05;                       ///< alphaOS only, [-1/3, 0]
    double dt = 0.01;                           ///< [s]
    double duration = 0.0;                      ///< [s]; <= 0 whole record
    bool allowUnstable = false;
};

/// Online model updating (docs/method.md, Online model updating to The paper's UKF); absent or
/// enabled = false: no updating.
struct UpdatingSpec {
    bool enabled = false;
    std::string specimen;            ///< the experimental element identified
    /// The specimen's basic DOF identified (updating.basicDof: 0 axial, 1 shear, 2 rotation of
    /// a link2d, default its primary); -1 for a one-DOF specimen (its one DOF).
    int basicDof = -1;
    /// The identified DOF's initial model: a one-DOF specimen's material, or a link2d
    /// specimen's updating.model (its basic DOFs carry no material).
    MaterialSpec model;
    std::string method = "ukf";      ///< "ukf" (Bouc-Wen) or "nelderMead" (Bouc-Wen, bilinear)
    ParameterBoundsMap bounds;       ///< per parameter; ukf default: Table III
    std::vector<std::string> parameters; ///< nelderMead: the fitted parameters
    /// "robust" (the default: RobustUkfIdentifier, anchored by calibrations of the history)
    /// or "paper" (the paper's UKF as published: UkfIdentifier with the settings below)
    std::string ukfFormulation = "robust";
    /// The specimen model's uRef / fRef when the configuration gives them (the robust UKF
    /// derives missing ones from the data)
    std::optional<double> modelURef, modelFRef;
    /// The robust UKF's seed: a previous run's record (HDF5) whose measured response of the
    /// element named `specimen` is calibrated before the test (docs/configuration.md,
    /// updating.ukf.seedRecord); a relative path is taken from the configuration's folder.
    /// "" for none.
    std::string seedRecord;
    // UKF settings of the paper's formulation (defaults: the paper's a, b, kappa = 3 - L)
    double ukfA = 1e-4, ukfB = 2.0;
    std::optional<double> ukfKappa;
    double forceNoise = 0.01;        ///< expected noise std of F / fRef
    double parameterNoise = 2e-4;    ///< random-walk std per step, fraction of bound width
    double initialStdFraction = 0.25;
    // Nelder-Mead
    int maxEvaluations = 300;
    double cooldown = 1.0;           ///< [s] between triggers
    double fitWindow = 0.0;          ///< [s] of history weighted in the fit; 0 = all
    /// "auto" (default: the calibration for boucWen / boucWenPinching, the simplex for the
    /// other laws), "calibration" (Levenberg-Marquardt, warm start plus multi-start, for the
    /// laws CalibrationDefaults knows) or "simplex" (the paper's Nelder-Mead simplex)
    std::string nelderMeadRefit = "auto";
    InspectorSettings inspector;
    ReporterPolicy policy = ReporterPolicy::EveryStep;
    int everyN = 10;
    /// onApproval: test time [s] between two proposals for a target (each supersedes the one
    /// still pending)
    double proposalInterval = Reporter::kDefaultProposalInterval;
    std::vector<ReporterTarget> targets;
    /// Headless decision for the onApproval policy: "manual" (queue), "approveAll", "rejectAll".
    std::string approval = "manual";
    int maxConsecutiveRejections = 20;
    /// The online offset check (ModelUpdater, OffsetCheck.h): "off" (default), "auto"
    /// (offsets proposed to the operator when the data ask for them) or "on" (every check's).
    std::string offsets = "off";
};

struct TestConfig {
    std::string name;
    std::string description;
    std::string sourcePath; ///< file it was read from ("" if built in code)
    std::vector<DofSpec> dofs;
    std::vector<std::pair<int, int>> equalDofs; ///< (master, slave)
    DampingSpec damping;
    std::vector<ElementSpec> elements;
    GroundMotionSpec groundMotion;
    AnalysisSpec analysis;
    UpdatingSpec updating;
    LinkSpec link; ///< the console's link protocol (the "controller" section)
    std::vector<SiteSpec> sites; ///< the "sites" section (empty: one site, "controller")
    nlohmann::json raw; ///< the document as read (for records and reports)
};

} // namespace hsmu
