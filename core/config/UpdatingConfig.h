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
/// The identifier cfg.updating names for the specimen's numerical model (its initial
/// parameters). Throws ConfigError.
std::unique_ptr<Identifier> buildIdentifier(const TestConfig& cfg,
                                            const HysteresisLaw& specimenModel);
/// Build the updater for cfg (nullptr if updating is disabled). Throws ConfigError.
std::unique_ptr<ModelUpdater> buildModelUpdater(const TestConfig& cfg);

} // namespace hsmu
