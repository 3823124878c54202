// The binner turns footprints into one list per cell; by depth, each list must go nearest first
// (the camera loop stops at the first sphere past its hit), ties by sphere, whatever its length
// and however the footprints are split among threads.

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "accel/candidate_grid.h"
#include "accel/candidate_tunables.h"

namespace hexray {
namespace {

// A grid of `columns` cells of side 1 across [0, columns) x [0, 1).
CandidateGrid rowOfCells(std::uint32_t columns) {
    CandidateGrid grid;
    grid.columns = columns;
    grid.rows = 1;
    return grid;
}

// A footprint inside cell `column` alone.
Footprint inCell(std::uint32_t sphere, std::uint32_t column, float depth) {
    const float u = float(column);
    return {sphere, u + 0.25f, 0.25f, u + 0.75f, 0.75f, depth};
}

struct BinnedLists {
    UninitializedVector<std::uint32_t> cellStarts;
    UninitializedVector<std::uint32_t> entries;

    std::vector<std::uint32_t> list(std::size_t cell) const {
        return {entries.begin() + cellStarts[cell], entries.begin() + cellStarts[cell + 1]};
    }
};

BinnedLists binByDepth(const CandidateGrid& grid, const std::vector<std::vector<Footprint>>& parts) {
    BinnedLists lists;
    std::size_t entries = 0;
    std::vector<std::span<const Footprint>> spans;
    for (const auto& part : parts) {
        entries += part.size();
        spans.emplace_back(part);
    }
    lists.cellStarts.resize(grid.cellCount() + 1);
    lists.entries.resize(entries);
    CellBinner binner(lists.cellStarts, lists.entries);
    lists.cellStarts[grid.cellCount()] = std::uint32_t(binner.bin(grid, spans, 0, true));
    return lists;
}

TEST(CellBinner, ByDepthListsGoNearestFirstTiesBySphere) {
    const CandidateGrid grid = rowOfCells(2);
    // Two threads' footprints, each in sphere order; cell 1 gets a negative depth (a sphere around
    // the view's origin), a tie and -0 against +0.
    const BinnedLists lists = binByDepth(
        grid, {{inCell(0, 0, 5.0f), inCell(1, 1, 2.0f), inCell(2, 1, -1.0f), inCell(3, 0, 1.0f), inCell(4, 1, 0.0f)},
               {inCell(5, 1, 2.0f), inCell(6, 0, 5.0f), inCell(7, 1, -0.0f), inCell(8, 0, 0.5f)}});
    EXPECT_EQ(lists.list(0), (std::vector<std::uint32_t>{8, 3, 0, 6}));
    EXPECT_EQ(lists.list(1), (std::vector<std::uint32_t>{2, 4, 7, 1, 5}));
}

TEST(CellBinner, ByDepthSortsListsLongerThanAnInsertionSortTakes) {
    const CandidateGrid grid = rowOfCells(1);
    const std::uint32_t count = 8 * candidates::kInsertionSortLength;
    std::mt19937 random(7);
    std::uniform_int_distribution<int> depthStep(-20, 20);  // many ties
    std::vector<std::vector<Footprint>> parts(3);
    std::vector<std::pair<float, std::uint32_t>> expected;
    for (std::uint32_t sphere = 0; sphere < count; ++sphere) {
        const float depth = float(depthStep(random)) * 0.25f;
        parts[sphere * parts.size() / count].push_back(inCell(sphere, 0, depth));
        expected.emplace_back(depth, sphere);
    }
    std::ranges::sort(expected);
    std::vector<std::uint32_t> spheres;
    for (const auto& [depth, sphere] : expected) {
        spheres.push_back(sphere);
    }
    EXPECT_EQ(binByDepth(grid, parts).list(0), spheres);
}

}  // namespace
}  // namespace hexray
