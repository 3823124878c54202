#include "util/closest_name.h"

#include <algorithm>

namespace hexray::inline util {
namespace {

// Longer names than this are no typos worth measuring (and a huge key must cost no quadratic time).
constexpr std::size_t kMaxMeasuredLength = 64;
constexpr std::size_t kMaxSuggestedDistance = 2;
// Beyond this many names of a fitting length (a generated scene's shaders), no suggestion: the
// message must not cost seconds.
constexpr std::size_t kMaxMeasuredCandidates = 65536;

}  // namespace

std::size_t editDistance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: two back for a swap, one back, and this one.
    std::vector<std::size_t> twoBack(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], twoBack[j - 2] + 1);
        }
        std::swap(twoBack, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string> closestName(std::string_view typed, const std::vector<std::string>& candidates) {
    if (typed.empty() || typed.size() > kMaxMeasuredLength)
        return std::nullopt;
    const std::size_t limit = std::min(kMaxSuggestedDistance, (typed.size() - 1) / 2);
    std::optional<std::string> best;
    std::size_t bestDistance = limit + 1;
    std::size_t measured = 0;
    for (const std::string& candidate : candidates) {
        const std::size_t lengthDifference =
            std::max(candidate.size(), typed.size()) - std::min(candidate.size(), typed.size());
        if (lengthDifference > limit)
            continue;  // at least that many insertions or deletions
        if (++measured > kMaxMeasuredCandidates)
            return std::nullopt;
        const std::size_t distance = editDistance(typed, candidate);
        if (distance > 0 && distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

}  // namespace hexray::util
