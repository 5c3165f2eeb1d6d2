#pragma once
// The option a mistyped name was probably meant to be, for "did you mean --t-max?".
#include <optional>
#include <string>
#include <vector>

namespace gg::detail {

// Edits (insert, delete, substitute, swap two neighbours) between a and b (optimal string alignment).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The name in `names` nearest to `typed`, if within a third of its length in edits (at least 1,
// at most 3): close enough that the user surely meant it. Ties go to the first in `names`.
std::optional<std::string> closest_name(const std::string& typed, const std::vector<std::string>& names);

}  // namespace gg::detail
