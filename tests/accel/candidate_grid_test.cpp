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

// Cells lie in bands of rows, column after column within a band: every cell has its own index,
// below the count, and a band's first columns share its first cache line of cell starts.
TEST(CandidateGrid, NumbersItsCellsInBandsOfRowsOnceEach) {
    for (const auto& [columns, rows] : {std::pair{1u, 1u}, std::pair{7u, 1u}, std::pair{5u, 9u}, std::pair{64u, 6u}}) {
        CandidateGrid grid;
        grid.columns = columns;
        grid.rows = rows;
        std::vector<int> seen(grid.cellCount(), 0);
        for (std::uint32_t row = 0; row < rows; ++row) {
            for (std::uint32_t column = 0; column < columns; ++column) {
                const std::size_t index = grid.cellIndex(column, row);
                ASSERT_LT(index, seen.size()) << column << ", " << row;
                ++seen[index];
            }
        }
        EXPECT_EQ(std::ranges::count(seen, 1), std::ptrdiff_t(seen.size())) << columns << " x " << rows;
    }
    CandidateGrid grid;
    grid.columns = 64;
    grid.rows = 6;  // a band of 4 rows, then one of 2
    EXPECT_EQ(grid.cellIndex(0, 3), 3u);
    EXPECT_EQ(grid.cellIndex(3, 3), 15u);  // 16 starts to a 64-byte line: 4 columns of the band
    EXPECT_EQ(grid.cellIndex(0, 4), 256u);
    EXPECT_EQ(grid.cellIndex(1, 5), 259u);  // the short band: 2 rows a column
}

}  // namespace
}  // namespace hexray
