#pragma once
// How many single-character edits (insert, delete, replace, swap of neighbours) turn one word
// into another, and the known word nearest a mistyped one: for "did you mean …" hints.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hexray::inline util {

// The optimal-string-alignment distance: Levenshtein's, with a swap of two neighbouring
// characters ("--widht") counted as one edit, the commonest typing slip.
inline std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t columns = b.size() + 1;
    std::vector<std::size_t> cost((a.size() + 1) * columns);
    for (std::size_t i = 0; i <= a.size(); ++i) {
        for (std::size_t j = 0; j <= b.size(); ++j) {
            if (i == 0 || j == 0) {
                cost[i * columns + j] = i + j;
                continue;
            }
            const std::size_t replaced = cost[(i - 1) * columns + j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            std::size_t best = std::min({cost[(i - 1) * columns + j] + 1, cost[i * columns + j - 1] + 1, replaced});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                best = std::min(best, cost[(i - 2) * columns + j - 2] + 1);
            }
            cost[i * columns + j] = best;
        }
    }
    return cost.back();
}

// The candidate nearest `word` within `maxDistance` edits (the first of equals), if any.
inline std::optional<std::string> nearestWord(std::string_view word, const std::vector<std::string>& candidates,
                                              std::size_t maxDistance = 2) {
    std::optional<std::string> nearest;
    std::size_t nearestDistance = maxDistance + 1;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(word, candidate);
        if (distance < nearestDistance) {
            nearest = candidate;
            nearestDistance = distance;
        }
    }
    return nearest;
}

}  // namespace hexray::util
