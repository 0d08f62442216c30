#pragma once
// TestFactory: builds the runnable objects a TestConfig describes: hysteresis laws, elements
// (numerical and experimental, the latter on in-process VirtualSpecimens), the structure,
// the integrator, the ground motion, and the HybridTest tying them.
// Errors: ConfigError naming the configuration file and the element or field at fault.

#include "core/config/TestConfig.h"
#include "core/groundmotion/GroundMotion.h"

#include <functional>
#include <memory>
#include <string>

namespace hsmu {

class ExperimentalControl;
class HybridTest;
class HysteresisLaw;
class Integrator;
class Structure;

/// Makes the control of an experimental element; the default builds a VirtualSpecimen from
/// spec.specimen. Later links (TCP, OpenFresco) plug in here without touching core/experiment.
using ControlFactory =
    std::function<std::unique_ptr<ExperimentalControl>(const ElementSpec& spec)>;

std::unique_ptr<HysteresisLaw> buildLaw(const MaterialSpec& m, const std::string& where);
std::unique_ptr<ExperimentalControl> buildVirtualSpecimen(const ElementSpec& spec);
std::unique_ptr<Structure> buildStructure(const TestConfig& cfg,
                                          const ControlFactory& controls = {});
std::unique_ptr<Integrator> buildIntegrator(const AnalysisSpec& a);
/// The record the spec names: a file (a relative path is taken from the configuration's
/// folder; callers that take a path from the command line make it absolute first) or the
/// built-in synthetic record; scaled, not yet resampled.
GroundMotion buildGroundMotion(const GroundMotionSpec& g, const std::string& configPath);
std::unique_ptr<HybridTest> buildHybridTest(const TestConfig& cfg,
                                            const ControlFactory& controls = {});

} // namespace hsmu
