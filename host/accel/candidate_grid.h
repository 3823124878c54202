#pragma once
// One grid of the candidate lists (candidate_lists.h): cells over a window of tangent
// coordinates, the boxes of the spheres a view sees (footprints), and the counting sort that
// turns footprints into one list per cell.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "accel/sphere_footprint.h"
#include "shader_interface.h"
#include "util/uninitialized_vector.h"

namespace hexray::inline accel {

// A sphere's box in one view, padded for the shader's look-up and rounded outward to float.
struct Footprint {
    std::uint32_t sphere;  // its record
    float u0, v0, u1, v1;
    float depth;  // from the view's origin, for lists in depth order (candidate_lists.cpp's DepthOrder)
};

// The float at or just below `x` (never above), without a look at the rounding.
float roundedDown(double x);

// `box` padded by the shader's float look-up error (a few units of float roundoff of its
// coordinates), rounded outward.
Footprint footprintOf(std::uint32_t sphere, const TangentBox& box, float depth);

// Cells over a window, as the shader looks them up: its floats, and the cells in bands of rows.
struct CandidateGrid {
    float u0 = 0;  // the window's first corner
    float v0 = 0;
    float uScale = 1;  // cells per unit
    float vScale = 1;
    std::uint32_t columns = 1;
    std::uint32_t rows = 1;
    std::uint32_t firstCell = 0;  // of all the lists' cells

    std::size_t cellCount() const { return std::size_t(columns) * rows; }
    // Where cell (column, row) lies among the grid's cells: in bands of rows (shader_interface.h's
    // CELL_BAND_ROWS), column after column within a band.
    std::size_t cellIndex(std::uint32_t column, std::uint32_t row) const {
        const std::uint32_t bandStart = row - row % gpu::CELL_BAND_ROWS;
        const std::uint32_t bandRows = std::min(gpu::CELL_BAND_ROWS, rows - bandStart);
        return std::size_t(bandStart) * columns + std::size_t(column) * bandRows + row % gpu::CELL_BAND_ROWS;
    }

    // The cells a footprint covers, wherever the shader's rounding may put a ray inside it.
    void cellRange(const Footprint& f, std::uint32_t& column0, std::uint32_t& row0, std::uint32_t& column1,
                   std::uint32_t& row1) const;
    std::size_t entries(const Footprint& f) const;
};

// A grid over `window` of cells of about `cell` on a side (at most 65536 across).
CandidateGrid gridOver(const TangentBox& window, double cell);

// Lists for the cells of grids, filled from footprints by a counting sort on several threads.
// Each thread's footprints follow the previous thread's in every list, so lists keep the
// footprints' order (or the spheres' depths' order, where given).
class CellBinner {
public:
    // Writes into `cellStarts` and `entries`, sized for every grid to come.
    CellBinner(UninitializedVector<std::uint32_t>& cellStarts, UninitializedVector<std::uint32_t>& entries)
        : cellStarts_(cellStarts), entries_(entries) {}

    // Bins `parts` (one span of footprints per thread) into `grid`'s cells, from entry
    // `firstEntry` on; returns the entry after the last. `byDepth`: each list then goes in order of
    // its footprints' depths, ties by sphere (the footprints' order where they come by sphere).
    std::size_t bin(const CandidateGrid& grid, std::span<const std::span<const Footprint>> parts,
                    std::size_t firstEntry, bool byDepth = false);

private:
    // Each of `grid`'s lists, from entry `firstEntry` to `endEntry`, in order of their `keys` (one per
    // entry, from firstEntry on; candidate_grid.cpp's depthKey), on `threads` threads.
    void sortByDepth(const CandidateGrid& grid, std::span<std::uint64_t> keys, std::size_t firstEntry,
                     std::size_t endEntry, unsigned threads);

    UninitializedVector<std::uint32_t>& cellStarts_;
    UninitializedVector<std::uint32_t>& entries_;
    std::vector<std::vector<std::uint32_t>> counts_;  // per part: counts, then write cursors
};

}  // namespace hexray::accel
