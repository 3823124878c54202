#include "accel/morton_order.h"

#include <algorithm>
#include <array>

#include <glm/common.hpp>

namespace hexray::inline accel {
namespace {

constexpr int kBitsPerAxis = 10;
constexpr std::uint32_t kCells = 1u << kBitsPerAxis;

// The low 10 bits of v, two zero bits after each.
std::uint32_t spread(std::uint32_t v) {
    v &= kCells - 1;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

}  // namespace

std::vector<std::uint32_t> mortonOrder(std::span<const glm::dvec3> points) {
    glm::dvec3 low(0.0);
    glm::dvec3 high(0.0);
    if (!points.empty()) {
        low = high = points.front();
    }
    for (const glm::dvec3& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 extent = high - low;
    const glm::dvec3 scale = glm::dvec3(kCells) / glm::max(extent, glm::dvec3(1e-300));
    // Each point's code above its index: sorting these sorts by code, ties by index.
    std::vector<std::uint64_t> keys(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 cell = glm::clamp((points[i] - low) * scale, 0.0, double(kCells - 1));
        const std::uint64_t code =
            spread(std::uint32_t(cell.x)) | spread(std::uint32_t(cell.y)) << 1 | spread(std::uint32_t(cell.z)) << 2;
        keys[i] = code << 32 | i;
    }
    // A stable radix sort, one axis's worth of code bits a pass.
    std::vector<std::uint64_t> sorted(keys.size());
    for (int pass = 0; pass < 3; ++pass) {
        const int shift = 32 + pass * kBitsPerAxis;
        std::array<std::uint32_t, kCells + 1> starts{};
        for (const std::uint64_t key : keys) {
            ++starts[((key >> shift) & (kCells - 1)) + 1];
        }
        for (std::uint32_t digit = 0; digit < kCells; ++digit) {
            starts[digit + 1] += starts[digit];
        }
        for (const std::uint64_t key : keys) {
            sorted[starts[(key >> shift) & (kCells - 1)]++] = key;
        }
        keys.swap(sorted);
    }
    std::vector<std::uint32_t> order(keys.size());
    std::transform(keys.begin(), keys.end(), order.begin(), [](std::uint64_t key) { return std::uint32_t(key); });
    return order;
}

}  // namespace hexray::accel
