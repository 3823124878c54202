#pragma once
// The median of the bench programs' rounds.

#include <algorithm>
#include <vector>

namespace hexray::inline bench {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

}  // namespace hexray::bench
