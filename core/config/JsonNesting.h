#pragma once
// JsonNesting: the nesting depth of a JSON text, found by a flat scan (no recursion, no
// allocation), so that a configuration nested deeper than limits::kMaxJsonDepth is refused
// with its line before any recursive parser or walk can overflow the stack (issue 26, D1).
// Strings (with their escapes) and the comments the loader accepts (// and /* */) are skipped.

#include <cstddef>
#include <optional>
#include <string_view>

namespace hsmu {

/// The byte offset of the first '[' or '{' that opens level maxDepth + 1 (the document's
/// outermost brackets are level 1); nullopt when the text never nests that deep.
std::optional<std::size_t> firstTooDeep(std::string_view text, int maxDepth);

} // namespace hsmu
