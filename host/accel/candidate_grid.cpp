#include "accel/candidate_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "accel/candidate_tunables.h"
#include "util/parallel_parts.h"

namespace hexray::inline accel {
namespace {

using namespace candidates;  // the tunables

// roundedDown's mirror (below).
float roundedUp(double x) {
    return float(x + std::abs(x) * 0x1p-22 + 0x1p-126);
}

template <typename Visit>
void forEachCell(const CandidateGrid& grid, std::span<const Footprint> footprints, const Visit& visit) {
    for (const Footprint& f : footprints) {
        std::uint32_t column0, row0, column1, row1;
        grid.cellRange(f, column0, row0, column1, row1);
        for (std::uint32_t row = row0; row <= row1; ++row) {
            for (std::uint32_t column = column0; column <= column1; ++column) {
                visit(grid.cellIndex(column, row), f);
            }
        }
    }
}

// A footprint's place in a list in depth order: its depth's bits, ordered as the floats are (a
// negative float's bits reversed), above its sphere, which breaks ties. -0 counts as +0.
std::uint64_t depthKey(const Footprint& f) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(f.depth + 0.0f);
    const std::uint32_t ordered = bits & 0x80000000u ? ~bits : bits | 0x80000000u;
    return std::uint64_t(ordered) << 32 | f.sphere;
}

// Lists hold a few spheres each: an insertion sort of those, a full sort of longer ones.
void sortKeys(std::span<std::uint64_t> keys) {
    if (keys.size() > kInsertionSortLength) {
        std::sort(keys.begin(), keys.end());
        return;
    }
    for (std::size_t i = 1; i < keys.size(); ++i) {
        const std::uint64_t key = keys[i];
        std::size_t j = i;
        for (; j > 0 && keys[j - 1] > key; --j) {
            keys[j] = keys[j - 1];
        }
        keys[j] = key;
    }
}

}  // namespace

// Rounding to float moves a number by at most half a unit in its last place (2^-24 of it); moving
// it by more than that first rounds outward, without a look at the result.
float roundedDown(double x) {
    return float(x - std::abs(x) * 0x1p-22 - 0x1p-126);
}

Footprint footprintOf(std::uint32_t sphere, const TangentBox& box, float depth) {
    const double size = std::max({std::abs(box.u0), std::abs(box.u1), std::abs(box.v0), std::abs(box.v1)});
    const double pad = kLookupPad * (1.0 + size);
    return {
        sphere, roundedDown(box.u0 - pad), roundedDown(box.v0 - pad), roundedUp(box.u1 + pad), roundedUp(box.v1 + pad),
        depth};
}

void CandidateGrid::cellRange(const Footprint& f, std::uint32_t& column0, std::uint32_t& row0, std::uint32_t& column1,
                              std::uint32_t& row1) const {
    const auto index = [](double position, std::uint32_t count) {
        return std::uint32_t(std::clamp(std::floor(position), 0.0, double(count - 1)));
    };
    column0 = index((double(f.u0) - u0) * uScale - kCellSlack, columns);
    column1 = index((double(f.u1) - u0) * uScale + kCellSlack, columns);
    row0 = index((double(f.v0) - v0) * vScale - kCellSlack, rows);
    row1 = index((double(f.v1) - v0) * vScale + kCellSlack, rows);
}

std::size_t CandidateGrid::entries(const Footprint& f) const {
    std::uint32_t column0, row0, column1, row1;
    cellRange(f, column0, row0, column1, row1);
    return std::size_t(column1 - column0 + 1) * (row1 - row0 + 1);
}

CandidateGrid gridOver(const TangentBox& window, double cell) {
    CandidateGrid grid;
    grid.columns = std::uint32_t(std::clamp(std::ceil(window.width() / cell), 1.0, kMaxCellsAcross));
    grid.rows = std::uint32_t(std::clamp(std::ceil(window.height() / cell), 1.0, kMaxCellsAcross));
    grid.u0 = roundedDown(window.u0);
    grid.v0 = roundedDown(window.v0);
    // The window's far edge maps a little inside the last cell, whatever the float rounding.
    const auto scale = [](double extent, std::uint32_t count) {
        return extent > 0 ? float(count / (extent * (1.0 + 1e-5))) : 1.0f;
    };
    grid.uScale = scale(window.u1 - grid.u0, grid.columns);
    grid.vScale = scale(window.v1 - grid.v0, grid.rows);
    return grid;
}

std::size_t CellBinner::bin(const CandidateGrid& grid, std::span<const std::span<const Footprint>> parts,
                            std::size_t firstEntry, bool byDepth) {
    const std::size_t cells = grid.cellCount();
    counts_.resize(parts.size());
    runParts(unsigned(parts.size()), [&](unsigned part) {
        std::vector<std::uint32_t>& counts = counts_[part];
        counts.assign(cells, 0);
        forEachCell(grid, parts[part], [&](std::size_t cell, const Footprint&) { ++counts[cell]; });
    });
    std::size_t next = firstEntry;
    for (std::size_t cell = 0; cell < cells; ++cell) {
        cellStarts_[grid.firstCell + cell] = std::uint32_t(next);
        for (std::vector<std::uint32_t>& counts : counts_) {
            const std::uint32_t count = counts[cell];
            counts[cell] = std::uint32_t(next);
            next += count;
        }
    }
    // By depth, each footprint's key goes where its entry will (less firstEntry), to sort by.
    UninitializedVector<std::uint64_t> keys(byDepth ? next - firstEntry : 0);
    runParts(unsigned(parts.size()), [&](unsigned part) {
        std::vector<std::uint32_t>& cursors = counts_[part];
        forEachCell(grid, parts[part], [&](std::size_t cell, const Footprint& f) {
            const std::uint32_t entry = cursors[cell]++;
            if (byDepth) {
                keys[entry - firstEntry] = depthKey(f);
            } else {
                entries_[entry] = f.sphere;
            }
        });
    });
    if (byDepth) {
        sortByDepth(grid, keys, firstEntry, next, unsigned(parts.size()));
    }
    return next;
}

void CellBinner::sortByDepth(const CandidateGrid& grid, std::span<std::uint64_t> keys, std::size_t firstEntry,
                             std::size_t endEntry, unsigned threads) {
    const std::size_t cells = grid.cellCount();
    runParts(threads, [&](unsigned part) {
        for (std::size_t cell = partBegin(cells, threads, part); cell < partBegin(cells, threads, part + 1); ++cell) {
            const std::size_t first = cellStarts_[grid.firstCell + cell];
            const std::size_t end = cell + 1 < cells ? cellStarts_[grid.firstCell + cell + 1] : endEntry;
            const std::span list = keys.subspan(first - firstEntry, end - first);
            sortKeys(list);
            for (std::size_t k = 0; k < list.size(); ++k) {
                entries_[first + k] = std::uint32_t(list[k]);
            }
        }
    });
}

}  // namespace hexray::accel
