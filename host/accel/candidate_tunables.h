#pragma once
// Every tunable of the GPU's candidate lists (candidate_lists.h), in one place. The data-driven
// kernel reads the lists for scenes past a generated kernel's capacity (gpu::SMALL_SCENE_CAPACITY
// nodes or lights) that have spheres (render_plan.cpp).

#include <cstddef>

#include "unit_roundoff.h"

namespace hexray::inline accel::candidates {

// --- Size: how fine the grids are, within what the device's buffers hold.
// At most this many list entries in all (4 bytes each) and as many cells; a scene whose lists do
// not fit with one cell per view is traced testing every node.
inline constexpr std::size_t kMaxEntries = std::size_t{24} << 20;
inline constexpr std::size_t kMaxCells = std::size_t{8} << 20;
// The camera's cells start at a pixel's size and the camera may take up to half of both budgets;
// the lights share what it leaves. Each grid's cells double in side until the grids fit.
inline constexpr std::size_t kCameraBudgetShareDivisor = 2;
// A light's cells start at about the median sphere footprint's larger side (each sphere then
// covers a few cells, each cell holds a few spheres); every this many records are sampled for it.
inline constexpr std::size_t kSideSampleStride = 8;
// A light's grid needs no more cells than the image has samples to look them up: at most this many
// per sample (a small image's lists are then built in a blink, a large one's are unchanged).
inline constexpr std::size_t kLightCellsPerSample = 4;
// No grid is more than this many cells across.
inline constexpr double kMaxCellsAcross = 65536;
// f32-naive shadow rays start at the surface, and their rounding grows with their length.
// A light's lists hold rays as long as the longest the image can need on each cube face (to the
// farthest sphere, or to the farthest point of a plane a corner of the image sees) and this share
// more, for the shader's rounding of the ray's length; unless a corner ray meets a plane at a
// slope below kLeastPlaneSlope or not at all (the horizon in view): then up to
// kTextbookReachFactor times the farthest sphere or the eye, and a longer ray (off a far plane)
// takes a list of every sphere.
inline constexpr double kTextbookReachFactor = 2.0;
inline constexpr double kTextbookReachSlack = 1e-3;
inline constexpr double kLeastPlaneSlope = 1e-3;

// --- Conservative margins: smaller ones would let a list miss a sphere the shader's own
// floating-point test reports (tests/gpu/gpu_candidates_test.cpp compares against every node).
// A bound on the rounding of the shader's tests, in units of its roundoff of the magnitudes
// involved. The error estimates in shaders/intersect.glsl put the robust discriminant within
// about 6 units of the line distance; this leaves a margin of two and more.
inline constexpr double kRoundingUnits = 64.0;
// The textbook b^2 - 4ac (f32-naive), over 4, errs by at most 16 units of |f|^2 (f = origin -
// centre, one rounding of the exact difference: b^2 by 7 units of 4|f|^2, 4ac by 9, the
// subtraction by a unit of its result), and so does the square of the distance by which a ray it
// reports may miss: twice that.
inline constexpr double kTextbookRoundingUnits = 32.0;
// Camera rays land up to half a pixel past the image's edge (the sample pattern); the camera's
// view covers a margin of this many pixels.
inline constexpr double kImageMarginPixels = 2.0;
// A cube face's window reaches this far past the face, for directions the shader may give to
// either of two faces.
inline constexpr double kFaceMargin = 1e-6;
// The shader looks cells up in float whatever its precision: its tangent coordinates err by a few
// units of float roundoff of their size (a footprint reaches kLookupPad times 1 + its largest
// coordinate past its computed edges), and its cell index by a few units of roundoff of the
// grid's size (a footprint's cell range reaches kCellSlack cells further).
inline constexpr double kLookupPad = 16.0 * FLOAT32_UNIT_ROUNDOFF;
inline constexpr double kCellSlack = 0.02;
// Slack for the footprint's own rounding on the host, in tangent units: a few hundred units of
// double roundoff of the magnitudes involved, far below any float the shader computes.
inline constexpr double kFootprintSlack = 1e-12;

// --- Speed: a large scene's spheres are placed on every core, in parts of at least this many.
inline constexpr std::size_t kSpheresPerPlacingPart = std::size_t{1} << 16;
// A list in depth order is sorted by insertion up to this length (most hold a few spheres), and
// by std::sort past it (a list of thousands, as a view along a row of spheres may have).
inline constexpr std::size_t kInsertionSortLength = 32;

}  // namespace hexray::accel::candidates
