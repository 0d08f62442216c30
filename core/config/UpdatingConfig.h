#pragma once
// UpdatingConfig: the "updating" section of a test configuration (docs/configuration.md)
// and the ModelUpdater it describes.

#include "core/config/JsonCursor.h"
#include "core/config/TestConfig.h"

#include <memory>

namespace hsmu {

class HysteresisLaw;
class Identifier;
class ModelUpdater;

/// Parse the "updating" object; elements are checked against cfg.elements.
UpdatingSpec parseUpdating(const JsonCursor& c, const TestConfig& cfg);
/// The identifier u describes (u.method "ukf" or "nelderMead") for a specimen whose initial
/// numerical model is `model`; dt [s] converts the Nelder-Mead cooldown and window to steps.
/// Throws ConfigError starting with `where` (a model the method cannot identify, bad bounds).
std::unique_ptr<Identifier> buildIdentifier(const UpdatingSpec& u, const HysteresisLaw& model,
                                            double dt, const std::string& where);
/// Build the updater for cfg (nullptr if updating is disabled). Throws ConfigError.
std::unique_ptr<ModelUpdater> buildModelUpdater(const TestConfig& cfg);

} // namespace hsmu
