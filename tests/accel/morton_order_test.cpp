// The records' order: a permutation, deterministic, and along a Z-curve (neighbours in the order
// are neighbours in space).

#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "accel/morton_order.h"

namespace hexray {
namespace {

std::vector<glm::dvec3> randomPoints(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 engine(seed);
    std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
    std::vector<glm::dvec3> points(count);
    for (glm::dvec3& p : points) {
        p = {coordinate(engine), coordinate(engine), coordinate(engine)};
    }
    return points;
}

TEST(MortonOrder, IsAPermutation) {
    const std::vector<glm::dvec3> points = randomPoints(5000, 1);
    std::vector<std::uint32_t> order = mortonOrder(points);
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> identity(points.size());
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(order, identity);
    EXPECT_TRUE(mortonOrder(std::vector<glm::dvec3>{}).empty());
}

TEST(MortonOrder, FollowsAZCurveThroughTheOctants) {
    // The corners of a cube: the curve visits them in the order of their bits (x lowest).
    std::vector<glm::dvec3> corners;
    for (int bits = 7; bits >= 0; --bits) {
        corners.push_back({double(bits & 1), double((bits >> 1) & 1), double((bits >> 2) & 1)});
    }
    EXPECT_EQ(mortonOrder(corners), (std::vector<std::uint32_t>{7, 6, 5, 4, 3, 2, 1, 0}));
}

TEST(MortonOrder, PutsNeighboursInSpaceNextToEachOther) {
    const std::vector<glm::dvec3> points = randomPoints(20000, 2);
    const auto meanStep = [&](const std::vector<std::uint32_t>& order) {
        double sum = 0;
        for (std::size_t i = 1; i < order.size(); ++i) {
            sum += glm::distance(points[order[i - 1]], points[order[i]]);
        }
        return sum / double(order.size() - 1);
    };
    std::vector<std::uint32_t> given(points.size());
    std::iota(given.begin(), given.end(), 0u);
    // Random order steps about 100 apart; a space-filling curve through 20000 points about 200 / 27.
    EXPECT_LT(meanStep(mortonOrder(points)), 0.1 * meanStep(given));
}

TEST(MortonOrder, KeepsTheGivenOrderOfPointsInOneCell) {
    const std::vector<glm::dvec3> points = {{0, 0, 0}, {5, 5, 5}, {0, 0, 0}, {0, 0, 0}};
    EXPECT_EQ(mortonOrder(points), (std::vector<std::uint32_t>{0, 2, 3, 1}));
}

}  // namespace
}  // namespace hexray
