#pragma once
// Candidate lists for the data-driven kernel's HEXRAY_CANDIDATES variant (shaders/candidates.glsl):
// which spheres a ray can meet, by its direction, binned on the host. Camera rays all start at the
// eye, so a grid over the directions the eye sees lists, per cell, the spheres whose outline
// reaches into it; shadow rays all end at a light, so a grid over each face of a cube around the
// light (Haines and Greenberg's light buffer) lists the spheres between the light and the points
// in that direction. A ray then costs what its cell holds, about the depth of the scene along it,
// whatever the number of spheres.
//
// Conservative: every sphere the shader's own floating-point test could report along a ray in a
// cell is in that cell's list. Each sphere is binned with its radius stretched by a bound on the
// rounding of that test (the camera ray's direction, the centre's rounding to the shader's
// floats, the discriminant's cancellation in the textbook form), and each box by a bound on the
// rounding of the shader's own look-up. The shader then gives the same image as testing every
// node (tests/gpu/gpu_candidates_test.cpp checks it).
//
// This is the GPU's structure only: the CPU reference keeps its own BVH (accel/bvh.h).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "accel/candidate_tunables.h"
#include "layout/gpu_layout.h"
#include "precision/arithmetic.h"
#include "scene/scene.h"
#include "util/uninitialized_vector.h"

namespace hexray::inline accel {

struct CandidateLists {
    gpu::GpuCandidateAxes cameraAxes{};
    std::vector<gpu::GpuCandidateGrid> grids;       // the camera's, then gpu::CUBE_FACES per light
    UninitializedVector<std::uint32_t> cellStarts;  // one per cell, and the end of the last list
    // List after list: the planes' node indices (cell gpu::PLANE_CELL), then records: in depth
    // order from the eye in a robust kernel's camera lists (the grid's reach.y says so), ascending
    // in every other list.
    UninitializedVector<std::uint32_t> entries;
    // Each record's sphere, as its node index: the spheres in Morton order (morton_order.h), so
    // that neighbouring rays read neighbouring records.
    std::vector<std::uint32_t> sphereNodes;
    double buildMilliseconds = 0;

    // The grid buffer's contents: the camera's axes, then the grids; and their size.
    std::vector<std::byte> gridBytes() const;
    std::size_t gridByteCount() const { return sizeof cameraAxes + grids.size() * sizeof(gpu::GpuCandidateGrid); }
};

// How large the lists may grow: candidate_tunables.h's budgets (a test may give smaller ones).
struct CandidateBudget {
    std::size_t entries = candidates::kMaxEntries;
    std::size_t cells = candidates::kMaxCells;
};

// The lists for `scene` in the shader's placement, float width and formulation, built by
// `threadCount` threads (0: one per core; never more, whatever the number of lights); nothing when
// the camera's would not fit half the budget (the scene is then traced testing every node). The
// lights share the rest equally; a light whose lists would not fit its share takes one list of
// every sphere instead. Deterministic: the same scene gives the same lists on any number of threads.
std::optional<CandidateLists> buildCandidateLists(const Scene& scene, const Placement& placement, FloatWidth width,
                                                  Formulation formulation, unsigned threadCount = 0,
                                                  const CandidateBudget& budget = {});

}  // namespace hexray::accel
