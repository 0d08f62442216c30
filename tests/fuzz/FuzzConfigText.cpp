// libFuzzer target for the configuration loader's text stage (core/config/ConfigLoader.cpp's
// loadConfigFile): the nesting scan (JsonNesting) and then nlohmann's parser with comments,
// exactly as the loader runs them. Text nested past limits::kMaxJsonDepth must be found by the
// scan (the parser never sees it); anything else must parse or throw a json exception. The
// schema walk (parseConfig) needs all of core and is exercised by test_config_malformed_inputs.
#include "core/config/JsonNesting.h"
#include "core/util/InputLimits.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (hsmu::firstTooDeep(text, hsmu::limits::kMaxJsonDepth))
        return 0;
    try {
        const auto doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
        // What parsed is re-read from its own dump: the same document.
        if (nlohmann::json::parse(doc.dump()) != doc && doc == doc)
            std::abort();
    } catch (const nlohmann::json::exception&) {
    }
    return 0;
}
