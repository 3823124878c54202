#include "accel/candidate_lists.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "accel/candidate_grid.h"
#include "accel/candidate_tunables.h"
#include "accel/morton_order.h"
#include "accel/sphere_footprint.h"
#include "shader_interface.h"
#include "util/milliseconds_since.h"
#include "util/parallel_parts.h"

namespace hexray::inline accel {
namespace {

using namespace candidates;  // the tunables

// ---------------------------------------------------------------- the scene, placed

struct PlacedSphere {
    glm::dvec3 center;
    double radius;
    std::uint32_t node;
    double centerSize;  // |center|
};

// How long a light's shadow rays its lists hold, by cube face: `length`, or any length (+inf). A
// longer ray (one the image may need when `longerRays`) takes the list of every sphere.
struct ShadowReach {
    std::array<double, gpu::CUBE_FACES> length = infiniteReach();
    bool longerRays = false;

    static std::array<double, gpu::CUBE_FACES> infiniteReach() {
        std::array<double, gpu::CUBE_FACES> length;
        length.fill(std::numeric_limits<double>::infinity());
        return length;
    }
};

struct PlacedScene {
    glm::dvec3 eye{0.0};
    double eyeSize = 0;                 // |eye|
    std::vector<PlacedSphere> spheres;  // in record order (morton_order.h)
    std::vector<std::uint32_t> planes;
    std::vector<double> planeHeights;  // of `planes`, placed
    std::vector<glm::dvec3> lights;
    std::vector<double> lightSizes;  // |light|
    std::vector<ShadowReach> shadowReach;
};

// The directions of the camera rays at the corners of the image and its margin, from the eye.
std::array<glm::dvec3, 4> cameraCorners(const Scene& scene) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const double marginX = kImageMarginPixels / scene.image.width;
    const double marginY = kImageMarginPixels / scene.image.height;
    std::array<glm::dvec3, 4> corners;
    for (int corner = 0; corner < 4; ++corner) {
        const double x = corner & 1 ? 1.0 + marginX : -marginX;
        const double y = corner & 2 ? 1.0 + marginY : -marginY;
        corners[corner] = glm::normalize(sheet.topLeft + x * sheet.right + y * sheet.down);
    }
    return corners;
}

std::array<glm::dvec3, 8> boxCorners(const glm::dvec3& low, const glm::dvec3& high) {
    std::array<glm::dvec3, 8> corners;
    for (int corner = 0; corner < 8; ++corner) {
        corners[corner] = {corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z};
    }
    return corners;
}

// Points around every point a camera ray can meet, and so every shadow ray's origin: the corners
// of the spheres' and the eye's box, and where the image's corner rays meet each plane (the hits of
// the rays between them fill the quadrilateral of those four). Nullopt when a corner ray runs away
// from a plane or along it (the horizon in view).
std::optional<std::vector<glm::dvec3>> shadowOriginHull(const PlacedScene& placed,
                                                        std::span<const glm::dvec3> boxCorners,
                                                        const std::array<glm::dvec3, 4>& corners) {
    std::vector<glm::dvec3> hull(boxCorners.begin(), boxCorners.end());
    for (const double height : placed.planeHeights) {
        const double rise = height - placed.eye.y;
        if (rise == 0.0) {
            continue;  // the eye on the plane sees it edge-on
        }
        for (const glm::dvec3& direction : corners) {
            if (!(rise * direction.y > 0.0 && std::abs(direction.y) >= kLeastPlaneSlope)) {
                return std::nullopt;
            }
            hull.push_back(placed.eye + (rise / direction.y) * direction);
        }
    }
    return hull;
}

// f32-naive's shadow rays start at the surface and their rounding grows with their length: each
// light's lists hold rays as long as the image's can be, face by face, when they are bounded. A
// ray the shader looks up on a face has its largest component along the face's axis, so it is at
// most sqrt(3) times as long as the hull reaches from the light along that axis.
ShadowReach textbookReach(const std::optional<std::vector<glm::dvec3>>& hull, std::span<const glm::dvec3> boxCorners,
                          const glm::dvec3& light) {
    const std::span<const glm::dvec3> points = hull ? std::span<const glm::dvec3>(*hull) : boxCorners;
    double farthest = 0;
    std::array<double, gpu::CUBE_FACES> along{};
    for (const glm::dvec3& point : points) {
        const glm::dvec3 fromLight = point - light;
        farthest = std::max(farthest, glm::length(fromLight));
        for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
            along[face] = std::max(along[face], (face % 2 ? -1.0 : 1.0) * fromLight[int(face / 2)]);
        }
    }
    ShadowReach reach;
    reach.longerRays = !hull;
    const double nudge = double(gpu::TEXTBOOK_SHADOW_NUDGE);
    for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
        const double alongFace = std::sqrt(3.0) * (1.0 + kFaceMargin) * (along[face] + nudge);
        reach.length[face] = hull ? (1.0 + kTextbookReachSlack) * std::min(farthest + nudge, alongFace)
                                  : kTextbookReachFactor * farthest;
    }
    return reach;
}

// The placed spheres (node, centre and radius, in node order) in record order (morton_order.h),
// gathered on `threads` threads.
std::vector<PlacedSphere> placedInMortonOrder(std::span<const std::uint32_t> sphereNodes,
                                              std::span<const glm::dvec3> centers, std::span<const double> radii,
                                              unsigned threads) {
    const std::vector<std::uint32_t> order = mortonOrder(centers);
    std::vector<PlacedSphere> spheres(order.size());
    runAcrossCores(
        order.size(), kSpheresPerPlacingPart,
        [&](std::size_t first, std::size_t end) {
            for (std::size_t record = first; record < end; ++record) {
                const std::uint32_t i = order[record];
                spheres[record] = {centers[i], radii[i], sphereNodes[i], glm::length(centers[i])};
            }
        },
        threads);
    return spheres;
}

PlacedScene placeScene(const Scene& scene, const Placement& placement, Formulation formulation, unsigned threads) {
    PlacedScene placed;
    placed.eye = placement.position(scene.camera.position);
    placed.eyeSize = glm::length(placed.eye);
    std::vector<std::uint32_t> sphereNodes;
    std::vector<glm::dvec3> centers;
    std::vector<double> radii;
    sphereNodes.reserve(scene.nodes.size());
    centers.reserve(scene.nodes.size());
    radii.reserve(scene.nodes.size());
    glm::dvec3 low = placed.eye;
    glm::dvec3 high = placed.eye;
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        if (const auto* sphere = std::get_if<Sphere>(&scene.nodes[i].geometry)) {
            const glm::dvec3 center = placement.position(sphere->center);
            const double radius = placement.length(sphere->radius);
            low = glm::min(low, center - radius);
            high = glm::max(high, center + radius);
            sphereNodes.push_back(i);
            centers.push_back(center);
            radii.push_back(radius);
        } else {
            placed.planes.push_back(i);
            const double height = std::get<Plane>(scene.nodes[i].geometry).height;
            placed.planeHeights.push_back(placement.position({0.0, height, 0.0}).y);
        }
    }
    placed.spheres = placedInMortonOrder(sphereNodes, centers, radii, threads);
    const std::array<glm::dvec3, 8> box = boxCorners(low, high);
    const auto hull = shadowOriginHull(placed, box, cameraCorners(scene));
    for (const PointLight& light : scene.lights) {
        const glm::dvec3 position = placement.position(light.position);
        placed.lights.push_back(position);
        placed.lightSizes.push_back(glm::length(position));
        placed.shadowReach.push_back(formulation == Formulation::Textbook ? textbookReach(hull, box, position)
                                                                          : ShadowReach{});
    }
    return placed;
}

// ---------------------------------------------------------------- rounding

// The radius a sphere seems to have to the shader's tests: a ray that misses it by less may still
// be reported as a hit. `scale` is the magnitude of the coordinates and distances involved.
class Reach {
public:
    Reach(FloatWidth width, Formulation formulation)
        : unit_((formulation == Formulation::Textbook ? kTextbookRoundingUnits : kRoundingUnits) * unitRoundoff(width)),
          textbook_(formulation == Formulation::Textbook) {}

    // To a camera ray: `distance` from the eye; the sphere's centre and the eye are `center`
    // and `eye` large. The textbook test's b^2 - 4ac errs by a few units of |f|^2, f = eye - centre
    // being one rounding of the exact difference (textbookShadow); the float positions of the eye
    // and the centre err by a unit of theirs.
    double camera(double radius, double distance, double center, double eye) const {
        return textbook_ ? stretched(radius, distance + radius) + unit_ * (center + eye)
                         : stretched(radius, distance + radius + center + eye);
    }

    // To a shadow ray between a light `light` large and a point at most `rayLength` from it,
    // `distance` from the sphere.
    double shadow(double radius, double distance, double center, double light, double rayLength) const {
        return textbook_ ? textbookShadow(radius, distance, center, light, rayLength)
                         : stretched(radius, 2.0 * (distance + radius + center + light));
    }

private:
    // The robust tests err by a few units of the magnitudes; b^2 - 4ac by a few units of their
    // squares, which lets a ray up to sqrt(units) * |f| from the surface through.
    double stretched(double radius, double scale) const {
        const double rounding = unit_ * scale;
        return textbook_ ? std::sqrt(radius * radius + rounding * scale) + rounding : radius + rounding;
    }

    // The robust test starts at the light, whose roots err about as much again as the discriminant.
    // The textbook test starts at the point: its f = point - centre is one rounding of the exact
    // difference, so b^2 - 4ac errs by a few units of |f|^2 wherever the scene lies. A sphere it
    // reports lies along the ray between the point and the light, so |f| is at most the ray's
    // length less the sphere's distance from the light, and a few radii (and the seeming radius
    // and the roots' error, each up to a fraction sqrt(units) of |f|). Along the ray the roots err
    // by that fraction too: a sphere that close to the light may be reported behind it, so it
    // counts in every direction from the light.
    double textbookShadow(double radius, double distance, double center, double light, double rayLength) const {
        const double rootShare = std::sqrt(unit_);
        const double fromPoint = (std::max(rayLength - distance, 0.0) + 3.0 * radius) / (1.0 - 4.0 * rootShare);
        const double seeming = stretched(radius, fromPoint) + unit_ * (center + light);
        const bool nearLight = distance <= std::hypot(seeming, radius + rootShare * fromPoint);
        return nearLight ? 2.0 * distance + seeming : seeming;
    }

    double unit_;
    bool textbook_;
};

// ---------------------------------------------------------------- depth order

// The order of the camera's lists: a robust kernel's by depth from the eye (shader_interface.h's
// DEPTH_ORDER_UNITS), so that a ray stops at the first sphere past its nearest hit; a textbook
// kernel's by record, its tests erring too much for a depth to bound them.
class DepthOrder {
public:
    DepthOrder(FloatWidth width, Formulation formulation)
        : width_(width),
          margin_(gpu::DEPTH_ORDER_UNITS * unitRoundoff(width)),
          applies_(formulation == Formulation::Robust) {}

    bool applies() const { return applies_; }

    // The sphere's depth from `origin`, from the values the kernel holds (rounded to its floats),
    // rounded down; 0 when the order does not apply.
    float of(const glm::dvec3& origin, const PlacedSphere& s) const {
        if (!applies_) {
            return 0.0f;
        }
        const bool f32 = width_ == FloatWidth::F32;
        const glm::dvec3 center = f32 ? glm::dvec3(glm::vec3(s.center)) : s.center;
        const glm::dvec3 from = f32 ? glm::dvec3(glm::vec3(origin)) : origin;
        const double radius = f32 ? double(float(s.radius)) : s.radius;
        const double depth = glm::distance(center, from) * (1.0 - margin_) - radius * (1.0 + margin_);
        return roundedDown(depth);
    }

private:
    FloatWidth width_;
    double margin_;
    bool applies_;
};

// ---------------------------------------------------------------- views

TangentView cameraView(const Scene& scene) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    TangentView view;
    view.right = glm::normalize(sheet.right);
    view.down = glm::normalize(sheet.down);
    view.forward = glm::cross(view.down, view.right);
    // The sheet lies at distance 1: its point (x, y) of the image has tangent coordinates
    // left + |right| x / W, top + |down| y / H.
    const double left = glm::dot(sheet.topLeft, view.right);
    const double top = glm::dot(sheet.topLeft, view.down);
    const double marginX = kImageMarginPixels / scene.image.width;
    const double marginY = kImageMarginPixels / scene.image.height;
    const double width = glm::length(sheet.right);
    const double height = glm::length(sheet.down);
    view.window = {left - marginX * width, top - marginY * height, left + (1 + marginX) * width,
                   top + (1 + marginY) * height};
    return view;
}

// Face 2 * axis + (1 for the negative direction); its tangent axes are the next two, cyclically
// (as shaders/candidates.glsl's lightCandidates computes them).
TangentView cubeFace(std::uint32_t face) {
    const int axis = int(face / 2);
    TangentView view;
    view.forward = glm::dvec3(0.0);
    view.forward[axis] = face % 2 ? -1.0 : 1.0;
    view.right = glm::dvec3(0.0);
    view.right[(axis + 1) % 3] = 1.0;
    view.down = glm::dvec3(0.0);
    view.down[(axis + 2) % 3] = 1.0;
    const double edge = 1.0 + kFaceMargin;
    view.window = {-edge, -edge, edge, edge};
    return view;
}

// Whether a ball at `center` (from the cube's centre) of radius `radius` can show on `face`: a
// point of it must have its face component at least as large as the other two.
bool mayShowOnFace(const glm::dvec3& center, double radius, std::uint32_t face) {
    const int axis = int(face / 2);
    const double along = (face % 2 ? -1.0 : 1.0) * center[axis] + 2.0 * radius;
    const double across = std::max(std::abs(center[(axis + 1) % 3]), std::abs(center[(axis + 2) % 3]));
    return along * (1.0 + kFaceMargin) >= across;
}

// ---------------------------------------------------------------- what the views see

// One thread's share of what one view sees.
struct ViewPart {
    std::vector<Footprint> footprints;  // in record order
    std::optional<TangentBox> window;   // around them all
    std::vector<float> sampledSides;    // larger sides of the footprints of every kSideSampleStride-th record

    void add(std::uint32_t sphere, const TangentBox& box, float depth) {
        const Footprint f = footprintOf(sphere, box, depth);
        if (sphere % kSideSampleStride == 0) {
            sampledSides.push_back(std::max(f.u1 - f.u0, f.v1 - f.v0));
        }
        footprints.push_back(f);
        const TangentBox padded{f.u0, f.v0, f.u1, f.v1};
        window = window ? TangentBox{std::min(window->u0, padded.u0), std::min(window->v0, padded.v0),
                                     std::max(window->u1, padded.u1), std::max(window->v1, padded.v1)}
                        : padded;
    }

    void clear() {
        footprints.clear();
        window.reset();
        sampledSides.clear();
    }
};

// Some views (the camera's, or one light's cube faces) as seen by each thread that sighted them:
// parts[thread][view].
struct Sightings {
    std::vector<TangentView> views;
    std::vector<std::vector<ViewPart>> parts;

    std::vector<std::span<const Footprint>> footprints(std::size_t view) const {
        std::vector<std::span<const Footprint>> spans;
        for (const auto& part : parts) {
            spans.emplace_back(part[view].footprints);
        }
        return spans;
    }
};

// The camera's view, sighted by `threads` threads, each over its share of the spheres.
Sightings sightCamera(const PlacedScene& placed, const Scene& scene, const Reach& reach, const DepthOrder& depth,
                      unsigned threads) {
    Sightings sightings;
    sightings.views.push_back(cameraView(scene));
    sightings.parts.assign(threads, std::vector<ViewPart>(1));
    const std::size_t spheres = placed.spheres.size();
    runParts(threads, [&](unsigned thread) {
        ViewPart& part = sightings.parts[thread][0];
        for (std::size_t record = partBegin(spheres, threads, thread); record < partBegin(spheres, threads, thread + 1);
             ++record) {
            const PlacedSphere& s = placed.spheres[record];
            const glm::dvec3 fromEye = s.center - placed.eye;
            const double eyeReach = reach.camera(s.radius, glm::length(fromEye), s.centerSize, placed.eyeSize);
            if (const auto box = ballFootprint(sightings.views[0], fromEye, eyeReach)) {
                part.add(std::uint32_t(record), *box, depth.of(placed.eye, s));
            }
        }
    });
    return sightings;
}

// A light's cube faces, for one thread to sight light after light (sightFromLight).
Sightings lightFaces() {
    Sightings faces;
    for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
        faces.views.push_back(cubeFace(face));
    }
    faces.parts.assign(1, std::vector<ViewPart>(gpu::CUBE_FACES));
    return faces;
}

// What light `light`'s cube faces see, into `faces` (lightFaces), replacing the previous light's.
void sightFromLight(const PlacedScene& placed, const Reach& reach, std::size_t light, Sightings& faces) {
    std::vector<ViewPart>& parts = faces.parts[0];
    for (ViewPart& part : parts) {
        part.clear();
    }
    const std::array<double, gpu::CUBE_FACES>& rayLength = placed.shadowReach[light].length;
    for (std::uint32_t record = 0; record < placed.spheres.size(); ++record) {
        const PlacedSphere& s = placed.spheres[record];
        const glm::dvec3 fromLight = s.center - placed.lights[light];
        const double distance = glm::length(fromLight);
        double radius = 0;
        for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
            if (face == 0 || rayLength[face] != rayLength[face - 1]) {
                radius = reach.shadow(s.radius, distance, s.centerSize, placed.lightSizes[light], rayLength[face]);
            }
            if (!mayShowOnFace(fromLight, radius, face)) {
                continue;
            }
            if (const auto box = ballFootprint(faces.views[face], fromLight, radius)) {
                parts[face].add(record, *box, 0.0f);
            }
        }
    }
}

// ---------------------------------------------------------------- grids

// Grids for some of the views (the camera's, or one light's faces).
struct ViewSet {
    std::size_t firstView = 0;
    std::size_t viewCount = 0;
};

struct GridChoice {
    double side = 0;                   // of a cell
    std::vector<CandidateGrid> grids;  // one per view of the set
    std::size_t cells = 0;
    std::size_t entries = 0;
};

std::optional<TangentBox> viewWindow(const Sightings& sightings, std::size_t view) {
    std::optional<TangentBox> window;
    for (const auto& part : sightings.parts) {
        if (const auto& w = part[view].window) {
            window = window ? TangentBox{std::min(window->u0, w->u0), std::min(window->v0, w->v0),
                                         std::max(window->u1, w->u1), std::max(window->v1, w->v1)}
                            : *w;
        }
    }
    return window;
}

GridChoice gridsOfSide(const Sightings& sightings, const ViewSet& set, double cell) {
    GridChoice choice;
    choice.side = cell;
    for (std::size_t v = set.firstView; v < set.firstView + set.viewCount; ++v) {
        const auto window = viewWindow(sightings, v);
        choice.grids.push_back(window ? gridOver(*window, cell) : CandidateGrid{});
        choice.cells += choice.grids.back().cellCount();
    }
    std::vector<std::size_t> entries(sightings.parts.size(), 0);
    runParts(unsigned(sightings.parts.size()), [&](unsigned thread) {
        for (std::size_t v = 0; v < set.viewCount; ++v) {
            for (const Footprint& f : sightings.parts[thread][set.firstView + v].footprints) {
                entries[thread] += choice.grids[v].entries(f);
            }
        }
    });
    for (const std::size_t count : entries) {
        choice.entries += count;
    }
    return choice;
}

// The finest grids from cells of side `cell` on, doubling, within the budgets.
std::optional<GridChoice> chooseGrids(const Sightings& sightings, const ViewSet& set, double cell,
                                      std::size_t entryBudget, std::size_t cellBudget) {
    for (int doubling = 0; doubling < 64; ++doubling, cell *= 2.0) {
        GridChoice choice = gridsOfSide(sightings, set, cell);
        if (choice.entries <= entryBudget && choice.cells <= cellBudget) {
            return choice;
        }
        if (choice.cells == set.viewCount) {
            return std::nullopt;  // one cell a view and still too many entries
        }
    }
    return std::nullopt;
}

// A light's first cell side: the median sampled footprint side, or larger where that would make
// more than `cellBudget` cells over the light's windows.
double lightCellSide(const Sightings& sightings, const ViewSet& set, std::size_t cellBudget) {
    std::vector<float> sides;
    double area = 0;
    for (std::size_t v = set.firstView; v < set.firstView + set.viewCount; ++v) {
        if (const auto window = viewWindow(sightings, v)) {
            area += window->width() * window->height();
        }
        for (const auto& part : sightings.parts) {
            sides.insert(sides.end(), part[v].sampledSides.begin(), part[v].sampledSides.end());
        }
    }
    if (sides.empty()) {
        return 1.0;
    }
    const auto middle = sides.begin() + std::ptrdiff_t(sides.size() / 2);
    std::nth_element(sides.begin(), middle, sides.end());
    return std::max(double(*middle), std::sqrt(area / double(cellBudget)));
}

gpu::GpuCandidateGrid gpuGrid(const CandidateGrid& grid, std::uint32_t pastReachCell, float reach, bool depthOrder) {
    gpu::GpuCandidateGrid g{};
    g.window = glm::vec4(grid.u0, grid.v0, grid.uScale, grid.vScale);
    g.cells = glm::uvec4(grid.columns, grid.rows, grid.firstCell, pastReachCell);
    g.reach = glm::vec4(reach, depthOrder ? 1.0f : 0.0f, 0, 0);
    return g;
}

// A float no longer than `x`: a ray longer than it may be longer than x.
float floatNotAbove(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, 0.0f);
}

// ---------------------------------------------------------------- lights

// What each light may take: the lights share equally what the camera leaves, so that each light's
// lists depend on it alone and the lights can be built in any order, on any thread.
struct LightBudget {
    std::size_t entries = 0;
    std::size_t cells = 0;
};

// One light's grids: the side of their cells, or 0 when its lists do not fit its budget (its
// shadow rays then take the list of every sphere, as if they had no lists).
struct LightGridPlan {
    double cellSide = 0;
    std::size_t cells = 0;
    std::size_t entries = 0;
    // When no thread plans more than one light: what the light's faces see and their grids, kept
    // for writeLightGrids rather than sighted again.
    std::optional<Sightings> faces;
    std::vector<CandidateGrid> grids;
};

constexpr ViewSet kLightFaces{0, gpu::CUBE_FACES};

// Each light's grids, decided light by light on up to `threads` threads (each its own lights; the
// threads never depend on the number of lights), seeing the spheres anew for each light: only one
// light's footprints per thread exist at a time (and are kept when each thread has one light).
std::vector<LightGridPlan> planLightGrids(const PlacedScene& placed, const Reach& reach, const LightBudget& budget,
                                          unsigned threads) {
    const std::size_t lights = placed.lights.size();
    std::vector<LightGridPlan> plans(lights);
    const unsigned parts = unsigned(std::min<std::size_t>(threads, lights));
    if (parts == 0) {
        return plans;
    }
    const bool keep = lights <= threads;
    runParts(parts, [&](unsigned part) {
        Sightings faces = lightFaces();
        for (std::size_t light = partBegin(lights, parts, part); light < partBegin(lights, parts, part + 1); ++light) {
            sightFromLight(placed, reach, light, faces);
            const double side = lightCellSide(faces, kLightFaces, budget.cells);
            if (auto choice = chooseGrids(faces, kLightFaces, side, budget.entries, budget.cells)) {
                LightGridPlan& plan = plans[light];
                plan = {choice->side, choice->cells, choice->entries, std::nullopt, {}};
                if (keep) {
                    plan.faces = std::move(faces);
                    plan.grids = std::move(choice->grids);
                }
            }
        }
    });
    return plans;
}

// A grid whose every ray takes the list in `cell`: a ray longer than 0 is past its reach.
gpu::GpuCandidateGrid everySphereGrid(std::uint32_t cell) {
    gpu::GpuCandidateGrid g{};
    g.window = glm::vec4(-4.0f, -4.0f, 0.125f, 0.125f);  // any face's tangents land in its one cell
    g.cells = glm::uvec4(1, 1, cell, cell);
    g.reach = glm::vec4(0.0f, 0, 0, 0);
    return g;
}

// Where each light's cells and entries begin, from `firstCell` and `firstEntry` on, light after
// light; the last element is where the lights' end.
struct LightOffsets {
    std::vector<std::size_t> cells;
    std::vector<std::size_t> entries;
};

LightOffsets lightOffsets(std::span<const LightGridPlan> plans, std::size_t firstCell, std::size_t firstEntry) {
    LightOffsets offsets;
    offsets.cells.reserve(plans.size() + 1);
    offsets.entries.reserve(plans.size() + 1);
    for (const LightGridPlan& plan : plans) {
        offsets.cells.push_back(firstCell);
        offsets.entries.push_back(firstEntry);
        firstCell += plan.cells;
        firstEntry += plan.entries;
    }
    offsets.cells.push_back(firstCell);
    offsets.entries.push_back(firstEntry);
    return offsets;
}

// The lists' arrays are not zeroed before they are written (UninitializedVector): a count that
// differed from its plan would leave entries no one wrote, so it is an error.
void expectAsPlanned(std::size_t cell, std::size_t entry, std::size_t plannedCell, std::size_t plannedEntry) {
    if (cell != plannedCell || entry != plannedEntry) {
        throw std::logic_error("candidate lists: " + std::to_string(cell) + " cells and " + std::to_string(entry) +
                               " entries written where " + std::to_string(plannedCell) + " and " +
                               std::to_string(plannedEntry) + " were planned");
    }
}

// Fills each light's cells, entries and grids as planned, on up to `threads` threads; a light's
// shadow rays past its reach take `everySphereCell`.
void writeLightGrids(const PlacedScene& placed, const Reach& reach, std::span<LightGridPlan> plans,
                     const LightOffsets& offsets, std::uint32_t everySphereCell, CandidateLists& lists,
                     unsigned threads) {
    const std::size_t lights = plans.size();
    const unsigned parts = unsigned(std::min<std::size_t>(threads, lights));
    if (parts == 0) {
        return;
    }
    runParts(parts, [&](unsigned part) {
        Sightings faces = lightFaces();
        CellBinner binner(lists.cellStarts, lists.entries);
        for (std::size_t light = partBegin(lights, parts, part); light < partBegin(lights, parts, part + 1); ++light) {
            gpu::GpuCandidateGrid* grids = &lists.grids[1 + light * gpu::CUBE_FACES];
            if (plans[light].cellSide == 0) {
                std::fill(grids, grids + gpu::CUBE_FACES, everySphereGrid(everySphereCell));
                continue;
            }
            LightGridPlan& plan = plans[light];
            if (!plan.faces) {
                sightFromLight(placed, reach, light, faces);
                plan.grids = gridsOfSide(faces, kLightFaces, plan.cellSide).grids;
            }
            const Sightings& seen = plan.faces ? *plan.faces : faces;
            std::size_t cell = offsets.cells[light];
            std::size_t entry = offsets.entries[light];
            for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
                CandidateGrid& grid = plan.grids[face];
                grid.firstCell = std::uint32_t(cell);
                cell += grid.cellCount();
                entry = binner.bin(grid, seen.footprints(face), entry);
            }
            expectAsPlanned(cell, entry, offsets.cells[light + 1], offsets.entries[light + 1]);
            plan.faces.reset();  // its footprints are binned
            // A light whose rays all lie within its reach names a cell of its own (never taken).
            const ShadowReach& shadowReach = placed.shadowReach[light];
            const std::uint32_t pastReach = shadowReach.longerRays ? everySphereCell : plan.grids[0].firstCell;
            for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
                // In record order (DepthOrder applies to the camera's lists only).
                grids[face] = gpuGrid(plan.grids[face], pastReach, floatNotAbove(shadowReach.length[face]), false);
            }
        }
    });
}

// ---------------------------------------------------------------- assembly

// The cells before the lights': the planes', the camera's, and the list of every sphere.
class ListWriter {
public:
    ListWriter(CandidateLists& lists, std::size_t cells, std::size_t entries)
        : lists_(lists), binner_(lists.cellStarts, lists.entries) {
        lists_.cellStarts.resize(cells + 1);
        lists_.entries.resize(entries);
        lists_.cellStarts[cells] = std::uint32_t(entries);
    }

    // A cell holding `entries`.
    std::uint32_t cell(std::span<const std::uint32_t> entries) {
        lists_.cellStarts[nextCell_] = std::uint32_t(nextEntry_);
        std::copy(entries.begin(), entries.end(), lists_.entries.begin() + std::ptrdiff_t(nextEntry_));
        nextEntry_ += entries.size();
        return nextCell_++;
    }

    // A cell listing every record, 0 to `count` - 1.
    std::uint32_t everyRecord(std::size_t count) {
        lists_.cellStarts[nextCell_] = std::uint32_t(nextEntry_);
        for (std::size_t record = 0; record < count; ++record) {
            lists_.entries[nextEntry_++] = std::uint32_t(record);
        }
        return nextCell_++;
    }

    // Throws unless the next cell and entry are `cell` and `entry`.
    void expectAt(std::size_t cell, std::size_t entry) const { expectAsPlanned(nextCell_, nextEntry_, cell, entry); }

    // `grid`'s cells, from what `view` sees (`byDepth`: each list in depth order); sets their first cell.
    void grid(CandidateGrid& grid, const Sightings& sightings, std::size_t view, bool byDepth) {
        grid.firstCell = nextCell_;
        nextCell_ += std::uint32_t(grid.cellCount());
        const auto parts = sightings.footprints(view);
        nextEntry_ = binner_.bin(grid, parts, nextEntry_, byDepth);
    }

private:
    CandidateLists& lists_;
    CellBinner binner_;
    std::uint32_t nextCell_ = 0;
    std::size_t nextEntry_ = 0;
};

// The camera's grid, in the lists' first grid and the cells after the planes'.
void writeCameraGrid(ListWriter& writer, CandidateGrid grid, const Sightings& camera, bool depthOrder,
                     CandidateLists& lists) {
    writer.grid(grid, camera, 0, depthOrder);
    lists.grids[gpu::CAMERA_GRID] = gpuGrid(grid, grid.firstCell, std::numeric_limits<float>::infinity(), depthOrder);
    const TangentView& view = camera.views[0];
    lists.cameraAxes = {glm::vec4(glm::vec3(view.right), 0), glm::vec4(glm::vec3(view.down), 0),
                        glm::vec4(glm::vec3(view.forward), 0)};
}

}  // namespace

std::vector<std::byte> CandidateLists::gridBytes() const {
    std::vector<std::byte> bytes(sizeof cameraAxes + grids.size() * sizeof(gpu::GpuCandidateGrid));
    std::memcpy(bytes.data(), &cameraAxes, sizeof cameraAxes);
    std::memcpy(bytes.data() + sizeof cameraAxes, grids.data(), grids.size() * sizeof(gpu::GpuCandidateGrid));
    return bytes;
}

std::optional<CandidateLists> buildCandidateLists(const Scene& scene, const Placement& placement, FloatWidth width,
                                                  Formulation formulation, unsigned threadCount,
                                                  const CandidateBudget& total) {
    const auto start = std::chrono::steady_clock::now();
    const unsigned threads = threadsFor(threadCount);
    const PlacedScene placed = placeScene(scene, placement, formulation, threads);
    const Reach reach(width, formulation);
    const DepthOrder depth(width, formulation);
    const Sightings camera = sightCamera(placed, scene, reach, depth, threads);

    // The camera's cells start at a pixel's size and may take up to half the budgets; the lights
    // share what it leaves. One list of every sphere serves every light's rays past its reach
    // (f32-naive) and the lights whose lists do not fit.
    const std::size_t lightCount = placed.lights.size();
    const std::size_t everySphere = lightCount > 0 ? placed.spheres.size() : 0;
    const std::size_t fixedEntries = placed.planes.size() + everySphere;
    const std::size_t fixedCells = 1 + (lightCount > 0 ? 1 : 0);
    if (fixedEntries > total.entries || fixedCells > total.cells) {
        return std::nullopt;
    }
    const double pixel = glm::length(makePixelSheet(scene.camera, sheetAspect(scene)).right) / scene.image.width;
    const auto cameraGrid =
        chooseGrids(camera, {0, 1}, pixel, (total.entries - fixedEntries) / kCameraBudgetShareDivisor,
                    (total.cells - fixedCells) / kCameraBudgetShareDivisor);
    if (!cameraGrid) {
        return std::nullopt;
    }
    const std::size_t cells = fixedCells + cameraGrid->cells;
    const std::size_t entries = fixedEntries + cameraGrid->entries;
    const std::size_t samples = std::size_t(scene.image.width) * scene.image.height * scene.image.samplesPerPixel;
    const std::size_t lightShare = std::max<std::size_t>(lightCount, 1);
    const LightBudget budget{(total.entries - entries) / lightShare,
                             std::min((total.cells - cells) / lightShare, kLightCellsPerSample * samples)};
    std::vector<LightGridPlan> plans = planLightGrids(placed, reach, budget, threads);
    const bool listsEverySphere =
        std::ranges::any_of(plans, [](const LightGridPlan& plan) { return plan.cellSide == 0; }) ||
        std::ranges::any_of(placed.shadowReach, [](const ShadowReach& reach) { return reach.longerRays; });
    const bool unusedEverySphere = lightCount > 0 && !listsEverySphere;  // its cell and entries go unused
    const LightOffsets offsets =
        lightOffsets(plans, cells - (unusedEverySphere ? 1 : 0), entries - (unusedEverySphere ? everySphere : 0));

    CandidateLists lists;
    lists.grids.resize(1 + lightCount * gpu::CUBE_FACES);
    ListWriter writer(lists, offsets.cells.back(), offsets.entries.back());
    writer.cell(placed.planes);  // gpu::PLANE_CELL
    writeCameraGrid(writer, cameraGrid->grids[0], camera, depth.applies(), lists);
    const std::uint32_t everySphereCell = listsEverySphere ? writer.everyRecord(everySphere) : 0;
    writer.expectAt(offsets.cells.front(), offsets.entries.front());
    writeLightGrids(placed, reach, plans, offsets, everySphereCell, lists, threads);
    lists.sphereNodes.reserve(placed.spheres.size());
    for (const PlacedSphere& s : placed.spheres) {
        lists.sphereNodes.push_back(s.node);
    }
    lists.buildMilliseconds = millisecondsSince(start);
    return lists;
}

}  // namespace hexray::accel
