#include "gpu/candidate_lists.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "gpu/candidate_grid.h"
#include "gpu/candidate_tunables.h"
#include "gpu/morton_order.h"
#include "gpu/sphere_footprint.h"
#include "shader_interface.h"
#include "util/milliseconds_since.h"
#include "util/parallel_parts.h"

namespace hexray {
namespace {

using namespace candidates;  // the tunables

double roundoff(FloatWidth width) {
    return width == FloatWidth::F64 ? 0x1p-53 : 0x1p-24;
}

// ---------------------------------------------------------------- the scene, placed

struct PlacedSphere {
    glm::dvec3 center;
    double radius;
    std::uint32_t node;
};

struct PlacedScene {
    glm::dvec3 eye{0.0};
    double eyeSize = 0;  // |eye|
    std::vector<PlacedSphere> spheres;  // in record order (morton_order.h)
    std::vector<std::uint32_t> planes;
    std::vector<glm::dvec3> lights;
    std::vector<double> lightSizes;   // |light|
    std::vector<double> shadowReach;  // per light: the longest ray its lists hold (+inf: any)
};

std::vector<PlacedSphere> inMortonOrder(std::vector<PlacedSphere> spheres) {
    std::vector<glm::dvec3> centers(spheres.size());
    std::transform(spheres.begin(), spheres.end(), centers.begin(), [](const PlacedSphere& s) { return s.center; });
    std::vector<PlacedSphere> ordered;
    ordered.reserve(spheres.size());
    for (const std::uint32_t index : mortonOrder(centers)) {
        ordered.push_back(spheres[index]);
    }
    return ordered;
}

PlacedScene placeScene(const Scene& scene, const Placement& placement, Formulation formulation) {
    PlacedScene placed;
    placed.eye = placement.position(scene.camera.position);
    placed.eyeSize = glm::length(placed.eye);
    std::vector<PlacedSphere> spheres;
    spheres.reserve(scene.nodes.size());
    glm::dvec3 low = placed.eye;
    glm::dvec3 high = placed.eye;
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        if (const auto* sphere = std::get_if<Sphere>(&scene.nodes[i].geometry)) {
            const PlacedSphere s{placement.position(sphere->center), placement.length(sphere->radius), i};
            low = glm::min(low, s.center - s.radius);
            high = glm::max(high, s.center + s.radius);
            spheres.push_back(s);
        } else {
            placed.planes.push_back(i);
        }
    }
    placed.spheres = inMortonOrder(std::move(spheres));
    for (const PointLight& light : scene.lights) {
        const glm::dvec3 position = placement.position(light.position);
        placed.lights.push_back(position);
        placed.lightSizes.push_back(glm::length(position));
        double farthest = 0;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 point(corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z);
            farthest = std::max(farthest, glm::length(point - position));
        }
        placed.shadowReach.push_back(formulation == Formulation::Textbook ? kTextbookReachFactor * farthest
                                                                           : std::numeric_limits<double>::infinity());
    }
    return placed;
}

// ---------------------------------------------------------------- rounding

// The radius a sphere seems to have to the shader's tests: a ray that misses it by less may still
// be reported as a hit. `scale` is the magnitude of the coordinates and distances involved.
class Reach {
public:
    Reach(FloatWidth width, Formulation formulation)
        : unit_(kRoundingUnits * roundoff(width)), textbook_(formulation == Formulation::Textbook) {}

    // To a camera ray: `distance` from the eye; the sphere's centre and the eye are `center`
    // and `eye` large.
    double camera(double radius, double distance, double center, double eye) const {
        return stretched(radius, distance + radius + center + eye);
    }

    // To a shadow ray between a light `light` large and a point at most `rayLength` from it,
    // `distance` from the sphere. Robust: from the light, whose roots err about as much again as
    // the discriminant. Textbook: from the point, as large as the light and the ray together; its
    // root errs by up to the square root of the discriminant's error, so a sphere that far beyond
    // the light counts too.
    double shadow(double radius, double distance, double center, double light, double rayLength) const {
        const double scale = distance + radius + center + light;
        if (!textbook_) {
            return stretched(radius, 2.0 * scale);
        }
        const double fromPoint = scale + 2.0 * rayLength + light;
        return 2.0 * stretched(radius, fromPoint) + std::sqrt(unit_) * fromPoint;
    }

private:
    // The robust tests err by a few units of the magnitudes; b^2 - 4ac by a few units of their
    // squares, which lets a ray up to sqrt(units) * |f| from the surface through.
    double stretched(double radius, double scale) const {
        const double rounding = unit_ * scale;
        return textbook_ ? std::sqrt(radius * radius + rounding * scale) + rounding : radius + rounding;
    }

    double unit_;
    bool textbook_;
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

    void add(std::uint32_t sphere, const TangentBox& box) {
        const Footprint f = footprintOf(sphere, box);
        if (sphere % kSideSampleStride == 0) {
            sampledSides.push_back(std::max(f.u1 - f.u0, f.v1 - f.v0));
        }
        footprints.push_back(f);
        const TangentBox padded{f.u0, f.v0, f.u1, f.v1};
        window = window ? TangentBox{std::min(window->u0, padded.u0), std::min(window->v0, padded.v0),
                                     std::max(window->u1, padded.u1), std::max(window->v1, padded.v1)}
                        : padded;
    }
};

// views[v] as seen by each thread: parts[thread][v]. View 0 is the camera's, then CUBE_FACES per
// light.
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

void sightSphere(const PlacedScene& placed, const Sightings& sightings, const Reach& reach, std::uint32_t record,
                 std::vector<ViewPart>& part) {
    const PlacedSphere& s = placed.spheres[record];
    const double center = glm::length(s.center);
    const glm::dvec3 fromEye = s.center - placed.eye;
    const double eyeReach = reach.camera(s.radius, glm::length(fromEye), center, placed.eyeSize);
    if (const auto box = ballFootprint(sightings.views[0], fromEye, eyeReach)) {
        part[0].add(record, *box);
    }
    for (std::size_t light = 0; light < placed.lights.size(); ++light) {
        const glm::dvec3 fromLight = s.center - placed.lights[light];
        const double radius = reach.shadow(s.radius, glm::length(fromLight), center, placed.lightSizes[light],
                                           placed.shadowReach[light]);
        for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
            const std::size_t view = 1 + light * gpu::CUBE_FACES + face;
            if (!mayShowOnFace(fromLight, radius, face)) {
                continue;
            }
            if (const auto box = ballFootprint(sightings.views[view], fromLight, radius)) {
                part[view].add(record, *box);
            }
        }
    }
}

Sightings sight(const PlacedScene& placed, const Scene& scene, const Reach& reach, unsigned threads) {
    Sightings sightings;
    sightings.views.push_back(cameraView(scene));
    for (std::size_t light = 0; light < placed.lights.size(); ++light) {
        for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
            sightings.views.push_back(cubeFace(face));
        }
    }
    sightings.parts.assign(threads, std::vector<ViewPart>(sightings.views.size()));
    runParts(threads, [&](unsigned thread) {
        const std::size_t end = partBegin(placed.spheres.size(), threads, thread + 1);
        for (std::size_t record = partBegin(placed.spheres.size(), threads, thread); record < end; ++record) {
            sightSphere(placed, sightings, reach, std::uint32_t(record), sightings.parts[thread]);
        }
    });
    return sightings;
}

// ---------------------------------------------------------------- grids

// Grids for some of the views (the camera's, or one light's faces).
struct ViewSet {
    std::size_t firstView = 0;
    std::size_t viewCount = 0;
};

struct GridChoice {
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

gpu::GpuCandidateGrid gpuGrid(const CandidateGrid& grid, std::uint32_t pastReachCell, float reach) {
    gpu::GpuCandidateGrid g{};
    g.window = glm::vec4(grid.u0, grid.v0, grid.uScale, grid.vScale);
    g.cells = glm::uvec4(grid.columns, grid.rows, grid.firstCell, pastReachCell);
    g.reach = glm::vec4(reach, 0, 0, 0);
    return g;
}

// A float no longer than `x`: a ray longer than it may be longer than x.
float floatNotAbove(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, 0.0f);
}

// ---------------------------------------------------------------- assembly

class ListWriter {
public:
    ListWriter(CandidateLists& lists, std::size_t cells, std::size_t entries) : lists_(lists), binner_(lists.cellStarts, lists.entries) {
        lists_.cellStarts.resize(cells + 1);
        lists_.entries.resize(entries);
    }

    // A cell holding `entries`.
    std::uint32_t cell(std::span<const std::uint32_t> entries) {
        lists_.cellStarts[nextCell_] = std::uint32_t(nextEntry_);
        std::copy(entries.begin(), entries.end(), lists_.entries.begin() + std::ptrdiff_t(nextEntry_));
        nextEntry_ += entries.size();
        return nextCell_++;
    }

    // `grid`'s cells, from what `view` sees; sets their first cell.
    void grid(CandidateGrid& grid, const Sightings& sightings, std::size_t view) {
        grid.firstCell = nextCell_;
        nextCell_ += std::uint32_t(grid.cellCount());
        const auto parts = sightings.footprints(view);
        nextEntry_ = binner_.bin(grid, parts, nextEntry_);
    }

    void finish() { lists_.cellStarts[nextCell_] = std::uint32_t(nextEntry_); }

private:
    CandidateLists& lists_;
    CellBinner binner_;
    std::uint32_t nextCell_ = 0;
    std::size_t nextEntry_ = 0;
};

}  // namespace

std::vector<std::byte> CandidateLists::gridBytes() const {
    std::vector<std::byte> bytes(sizeof cameraAxes + grids.size() * sizeof(gpu::GpuCandidateGrid));
    std::memcpy(bytes.data(), &cameraAxes, sizeof cameraAxes);
    std::memcpy(bytes.data() + sizeof cameraAxes, grids.data(), grids.size() * sizeof(gpu::GpuCandidateGrid));
    return bytes;
}

std::size_t CandidateLists::cameraEntries() const {
    const gpu::GpuCandidateGrid& camera = grids[gpu::CAMERA_GRID];
    const std::size_t end = camera.cells.z + std::size_t(camera.cells.x) * camera.cells.y;
    return cellStarts[end] - cellStarts[camera.cells.z];
}

std::optional<CandidateLists> buildCandidateLists(const Scene& scene, const Placement& placement, FloatWidth width,
                                                  Formulation formulation, unsigned threadCount) {
    const auto start = std::chrono::steady_clock::now();
    const unsigned threads = threadsFor(threadCount);
    const PlacedScene placed = placeScene(scene, placement, formulation);
    const Sightings sightings = sight(placed, scene, Reach(width, formulation), threads);

    // The camera's cells start at a pixel's size and may take up to half the budgets; the lights
    // share what it leaves.
    const std::size_t lightCount = placed.lights.size();
    const bool textbook = formulation == Formulation::Textbook;
    const std::size_t fixedEntries = placed.planes.size() + (textbook ? lightCount * placed.spheres.size() : 0);
    std::size_t cells = 1 + (textbook ? lightCount : 0);
    if (fixedEntries > kMaxEntries) {
        return std::nullopt;
    }
    const double pixel = glm::length(makePixelSheet(scene.camera, sheetAspect(scene)).right) / scene.image.width;
    auto camera = chooseGrids(sightings, {0, 1}, pixel, (kMaxEntries - fixedEntries) / kCameraBudgetShareDivisor,
                              (kMaxCells - cells) / kCameraBudgetShareDivisor);
    if (!camera) {
        return std::nullopt;
    }
    cells += camera->cells;
    std::size_t entries = fixedEntries + camera->entries;
    const std::size_t samples = std::size_t(scene.image.width) * scene.image.height * scene.image.samplesPerPixel;
    std::vector<GridChoice> lightGrids;
    for (std::size_t light = 0; light < lightCount; ++light) {
        const ViewSet set{1 + light * gpu::CUBE_FACES, gpu::CUBE_FACES};
        const std::size_t entryBudget = (kMaxEntries - entries) / (lightCount - light);
        const std::size_t cellBudget =
            std::min((kMaxCells - cells) / (lightCount - light), kLightCellsPerSample * samples);
        auto choice = chooseGrids(sightings, set, lightCellSide(sightings, set, cellBudget), entryBudget, cellBudget);
        if (!choice) {
            return std::nullopt;
        }
        cells += choice->cells;
        entries += choice->entries;
        lightGrids.push_back(std::move(*choice));
    }

    CandidateLists lists;
    ListWriter writer(lists, cells, entries);
    writer.cell(placed.planes);  // gpu::PLANE_CELL
    CandidateGrid& cameraGrid = camera->grids[0];
    writer.grid(cameraGrid, sightings, 0);
    lists.grids.push_back(gpuGrid(cameraGrid, cameraGrid.firstCell, std::numeric_limits<float>::infinity()));
    const TangentView& view = sightings.views[0];
    lists.cameraAxes = {glm::vec4(glm::vec3(view.right), 0), glm::vec4(glm::vec3(view.down), 0),
                        glm::vec4(glm::vec3(view.forward), 0)};
    std::vector<std::uint32_t> everySphere;
    if (textbook) {
        everySphere.resize(placed.spheres.size());
        for (std::uint32_t record = 0; record < everySphere.size(); ++record) {
            everySphere[record] = record;
        }
    }
    for (std::size_t light = 0; light < lightCount; ++light) {
        for (std::size_t face = 0; face < gpu::CUBE_FACES; ++face) {
            writer.grid(lightGrids[light].grids[face], sightings, 1 + light * gpu::CUBE_FACES + face);
        }
        // f32-naive: a ray longer than the lists hold tests every sphere, listed in one more cell.
        const std::uint32_t pastReach = textbook ? writer.cell(everySphere) : lightGrids[light].grids[0].firstCell;
        for (const CandidateGrid& face : lightGrids[light].grids) {
            lists.grids.push_back(gpuGrid(face, pastReach, floatNotAbove(placed.shadowReach[light])));
        }
    }
    writer.finish();
    lists.sphereNodes.reserve(placed.spheres.size());
    for (const PlacedSphere& s : placed.spheres) {
        lists.sphereNodes.push_back(s.node);
    }
    lists.buildMilliseconds = millisecondsSince(start);
    return lists;
}

}  // namespace hexray
