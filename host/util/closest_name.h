#pragma once
// "Did you mean …": the known name closest to a mistyped one, by edit distance.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hexray::inline util {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring bytes each count 1 ("raduis" is 1 from "radius").
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest `typed`, if one is near enough to be what was meant: at most 2 edits,
// and fewer than half of `typed`'s length (so "x" suggests nothing). Ties go to the candidate
// listed first. None for an exact match (that was no typo), or among more than 65536 candidates
// of a fitting length.
std::optional<std::string> closestName(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace hexray::util
