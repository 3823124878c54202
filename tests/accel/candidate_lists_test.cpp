// The candidate lists on the host: every sphere a camera ray or a shadow ray meets (in exact
// arithmetic) is in the list of the cell the shader looks the ray up in (a model of
// shaders/candidates.glsl's float look-up), the lists are sorted, and any number of threads builds
// the same lists. tests/gpu/gpu_candidates_test.cpp checks the shader's own rounding.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "camera/camera.h"
#include "accel/candidate_lists.h"
#include "gpu/render_plan.h"
#include "scene/random_spheres.h"
#include "support/floor_scene.h"
#include "util/parallel_parts.h"

namespace hexray {
namespace {

// Cell (column, row) of a grid, as the shader finds it: in bands of CELL_BAND_ROWS rows (the last
// may be short), column after column within a band.
std::uint32_t cellOf(const gpu::GpuCandidateGrid& g, std::uint32_t column, std::uint32_t row) {
    const std::uint32_t band = row / gpu::CELL_BAND_ROWS;
    const std::uint32_t firstRow = band * gpu::CELL_BAND_ROWS;
    const std::uint32_t bandRows = std::min(gpu::CELL_BAND_ROWS, g.cells.y - firstRow);
    return g.cells.z + firstRow * g.cells.x + column * bandRows + (row - firstRow);
}

// Every cell of a grid.
std::vector<std::uint32_t> cellsOf(const gpu::GpuCandidateGrid& g) {
    std::vector<std::uint32_t> cells;
    for (std::uint32_t row = 0; row < g.cells.y; ++row) {
        for (std::uint32_t column = 0; column < g.cells.x; ++column) {
            cells.push_back(cellOf(g, column, row));
        }
    }
    return cells;
}

// The list the shader reads for tangent coordinates `tangent` in grid `grid` (gridCandidates).
std::set<std::uint32_t> listAt(const CandidateLists& lists, std::uint32_t grid, glm::vec2 tangent) {
    const gpu::GpuCandidateGrid& g = lists.grids.at(grid);
    const glm::vec2 position = (tangent - glm::vec2(g.window)) * glm::vec2(g.window.z, g.window.w);
    std::set<std::uint32_t> nodes;
    if (!(position.x >= 0 && position.y >= 0 && position.x < float(g.cells.x) && position.y < float(g.cells.y))) {
        return nodes;
    }
    const std::uint32_t cell = cellOf(g, std::uint32_t(position.x), std::uint32_t(position.y));
    for (std::uint32_t k = lists.cellStarts.at(cell); k < lists.cellStarts.at(cell + 1); ++k) {
        nodes.insert(lists.sphereNodes.at(lists.entries.at(k)));
    }
    return nodes;
}

std::set<std::uint32_t> cameraList(const CandidateLists& lists, const glm::vec3& direction) {
    const glm::vec2 across(glm::dot(direction, glm::vec3(lists.cameraAxes.right)),
                           glm::dot(direction, glm::vec3(lists.cameraAxes.down)));
    return listAt(lists, gpu::CAMERA_GRID, across / glm::dot(direction, glm::vec3(lists.cameraAxes.forward)));
}

// The cube face the shader looks a direction from a light up on (lightCandidates): its largest
// component's axis; the face's tangent axes are the next two, cyclically.
template <typename Vec3>
std::uint32_t faceOf(const Vec3& fromLight) {
    const Vec3 size = glm::abs(fromLight);
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    return 2 * std::uint32_t(axis) + (fromLight[axis] < 0 ? 1u : 0u);
}

std::set<std::uint32_t> lightList(const CandidateLists& lists, std::uint32_t light, const glm::vec3& fromLight) {
    const std::uint32_t face = faceOf(fromLight);
    const int axis = int(face / 2);
    const glm::vec2 across(fromLight[(axis + 1) % 3], fromLight[(axis + 2) % 3]);
    return listAt(lists, gpu::CAMERA_GRID + 1 + gpu::CUBE_FACES * light + face, across / std::abs(fromLight[axis]));
}

// Directions from `origin` that graze the sphere: `count` of them around its outline, a
// millionth of its angular radius inside.
std::vector<glm::dvec3> grazingDirections(const glm::dvec3& origin, const glm::dvec3& center, double radius,
                                          int count) {
    const glm::dvec3 axis = glm::normalize(center - origin);
    const double halfAngle = std::asin(radius / glm::distance(center, origin)) * (1.0 - 1e-6);
    const glm::dvec3 side =
        glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(axis, side);
    std::vector<glm::dvec3> directions;
    for (int k = 0; k < count; ++k) {
        const double around = 2.0 * 3.14159265358979 * k / count;
        directions.push_back(std::cos(halfAngle) * axis +
                             std::sin(halfAngle) * (std::cos(around) * side + std::sin(around) * up));
    }
    return directions;
}

Scene testScene(std::uint32_t spheres) {
    Scene scene = makeRandomSpheresScene(spheres, 3);
    scene.image.width = 320;
    scene.image.height = 180;
    return scene;
}

TEST(CandidateLists, HoldEverySphereACameraRayGrazes) {
    const Scene scene = testScene(3000);
    const Placement placement = placementFor(scene, Formulation::Robust);
    const auto lists = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust);
    ASSERT_TRUE(lists);
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const glm::dvec3 forward = glm::normalize(glm::cross(sheet.down, sheet.right));
    const double corner = 1.0 / glm::length(sheet.topLeft);  // the image's least d . forward
    std::size_t checked = 0;
    for (std::uint32_t node = 1; node < scene.nodes.size(); ++node) {
        const auto& sphere = std::get<Sphere>(scene.nodes[node].geometry);
        const glm::dvec3 center = placement.position(sphere.center);
        for (const glm::dvec3& direction :
             grazingDirections(glm::dvec3(0.0), center, placement.length(sphere.radius), 16)) {
            if (glm::dot(direction, forward) < corner) {
                continue;  // out of the image
            }
            ++checked;
            ASSERT_TRUE(cameraList(*lists, glm::vec3(direction)).count(node)) << "node " << node;
        }
    }
    EXPECT_GT(checked, 20000u);
}

TEST(CandidateLists, HoldEverySphereAShadowRayGrazes) {
    const Scene scene = testScene(3000);
    const Placement placement = placementFor(scene, Formulation::Robust);
    const auto lists = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust);
    ASSERT_TRUE(lists);
    std::size_t checked = 0;
    for (std::uint32_t light = 0; light < scene.lights.size(); ++light) {
        const glm::dvec3 position = placement.position(scene.lights[light].position);
        for (std::uint32_t node = 1; node < scene.nodes.size(); ++node) {
            const auto& sphere = std::get<Sphere>(scene.nodes[node].geometry);
            const glm::dvec3 center = placement.position(sphere.center);
            for (const glm::dvec3& direction :
                 grazingDirections(position, center, placement.length(sphere.radius), 16)) {
                ++checked;
                ASSERT_TRUE(lightList(*lists, light, glm::vec3(direction)).count(node))
                    << "light " << light << ", node " << node;
            }
        }
    }
    EXPECT_EQ(checked, 2u * 3000u * 16u);
}

// The planes' cell, then each grid's cells, every sphere in one record; each list as `inOrder`
// says (given the grid and the list's spheres' nodes, in list order).
template <typename InOrder>
void expectListsAfterThePlanes(const Scene& scene, const CandidateLists& lists, const InOrder& inOrder) {
    ASSERT_EQ(lists.cellStarts.at(gpu::PLANE_CELL + 1), 1u);
    EXPECT_EQ(lists.entries.at(0), 0u);  // the floor, node 0
    EXPECT_EQ(lists.cellStarts.back(), lists.entries.size());
    ASSERT_EQ(lists.grids.size(), 1 + gpu::CUBE_FACES * scene.lights.size());
    for (std::uint32_t grid = 0; grid < lists.grids.size(); ++grid) {
        for (const std::uint32_t cell : cellsOf(lists.grids[grid])) {
            std::vector<std::uint32_t> nodes;
            for (std::uint32_t k = lists.cellStarts.at(cell); k < lists.cellStarts.at(cell + 1); ++k) {
                nodes.push_back(lists.sphereNodes.at(lists.entries.at(k)));
            }
            ASSERT_TRUE(inOrder(grid, nodes)) << "grid " << grid << ", cell " << cell;
            std::sort(nodes.begin(), nodes.end());
            ASSERT_TRUE(std::adjacent_find(nodes.begin(), nodes.end()) == nodes.end()) << "cell " << cell;
        }
    }
    std::vector<std::uint32_t> nodes = lists.sphereNodes;
    std::sort(nodes.begin(), nodes.end());
    for (std::uint32_t i = 0; i < nodes.size(); ++i) {
        ASSERT_EQ(nodes[i], i + 1);  // every sphere has one record
    }
}

// Each sphere node's record.
std::vector<std::uint32_t> recordsOfNodes(const Scene& scene, const CandidateLists& lists) {
    std::vector<std::uint32_t> recordOf(scene.nodes.size());
    for (std::uint32_t record = 0; record < lists.sphereNodes.size(); ++record) {
        recordOf.at(lists.sphereNodes[record]) = record;
    }
    return recordOf;
}

// Whether `nodes` (a list's, in list order) go in record order.
bool inRecordOrder(const std::vector<std::uint32_t>& recordOf, const std::vector<std::uint32_t>& nodes) {
    return std::is_sorted(nodes.begin(), nodes.end(),
                          [&](std::uint32_t a, std::uint32_t b) { return recordOf.at(a) < recordOf.at(b); });
}

// A robust kernel's camera lists are in depth order from the eye (shader_interface.h): each
// sphere's |f| - r is at least the one before's, but for the depth margin (DEPTH_ORDER_UNITS units
// of the width's roundoff of |f| + r, each side) and the depth's rounding to float; the lights'
// lists keep record order.
TEST(CandidateLists, ListThePlanesFirstThenRobustCameraListsInDepthOrder) {
    const Scene scene = testScene(500);
    for (const FloatWidth width : {FloatWidth::F32, FloatWidth::F64}) {
        const auto lists =
            buildCandidateLists(scene, placementFor(scene, Formulation::Robust), width, Formulation::Robust);
        ASSERT_TRUE(lists);
        const std::vector<std::uint32_t> recordOf = recordsOfNodes(scene, *lists);
        const double margin = 2.0 * gpu::DEPTH_ORDER_UNITS * unitRoundoff(width) + 0x1p-22;
        const auto depthOrdered = [&](const std::vector<std::uint32_t>& nodes) {
            double before = -std::numeric_limits<double>::infinity();
            double beforeSize = 0;
            for (const std::uint32_t node : nodes) {
                const Sphere& sphere = std::get<Sphere>(scene.nodes.at(node).geometry);
                const double distance = glm::distance(sphere.center, scene.camera.position);
                const double depth = distance - sphere.radius;
                if (depth < before - margin * (beforeSize + distance + sphere.radius)) {
                    return false;
                }
                before = depth;
                beforeSize = distance + sphere.radius;
            }
            return true;
        };
        expectListsAfterThePlanes(scene, *lists, [&](std::uint32_t grid, const std::vector<std::uint32_t>& nodes) {
            if (grid == gpu::CAMERA_GRID) {
                return depthOrdered(nodes) && lists->grids[grid].reach.y == 1.0f;  // and the shader is told so
            }
            return inRecordOrder(recordOf, nodes) && lists->grids[grid].reach.y == 0.0f;
        });
    }
}

// A textbook kernel's tests err too much for a depth to bound them: its lists keep record order.
TEST(CandidateLists, ListThePlanesFirstThenTextbookListsInRecordOrder) {
    const Scene scene = testScene(500);
    const auto lists =
        buildCandidateLists(scene, placementFor(scene, Formulation::Textbook), FloatWidth::F32, Formulation::Textbook);
    ASSERT_TRUE(lists);
    const std::vector<std::uint32_t> recordOf = recordsOfNodes(scene, *lists);
    expectListsAfterThePlanes(scene, *lists, [&](std::uint32_t grid, const std::vector<std::uint32_t>& nodes) {
        return inRecordOrder(recordOf, nodes) && lists->grids[grid].reach.y == 0.0f;
    });
}

// `scene` with `count` lights spread over a square above its spheres.
Scene withLights(Scene scene, std::size_t count) {
    scene.lights.clear();
    for (std::size_t i = 0; i < count; ++i) {
        scene.lights.push_back(
            PointLight{{double(i % 37) - 18.0, 40.0 + double(i % 7), double(i / 37)}, Color(1.0), 10.0});
    }
    return scene;
}

TEST(CandidateLists, AreTheSameOnAnyNumberOfThreads) {
    // Few lights (each light's spheres on one thread), more lights than threads, and enough spheres
    // to be placed in several parts (kSpheresPerPlacingPart).
    const auto placedInParts = std::uint32_t(3 * candidates::kSpheresPerPlacingPart);
    for (const Scene& scene : {testScene(4000), withLights(testScene(400), 40), testScene(placedInParts)}) {
        const Placement placement = placementFor(scene, Formulation::Robust);
        const auto one = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust, 1);
        ASSERT_TRUE(one);
        for (const unsigned threads : {2u, 3u, 8u}) {
            const auto many = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust, threads);
            ASSERT_TRUE(many);
            EXPECT_EQ(many->entries, one->entries) << threads << " threads";
            EXPECT_EQ(many->cellStarts, one->cellStarts) << threads << " threads";
            EXPECT_EQ(many->sphereNodes, one->sphereNodes) << threads << " threads";
            EXPECT_EQ(many->gridBytes(), one->gridBytes()) << threads << " threads";
        }
    }
}

TEST(CandidateLists, ManyLightsStartNoMoreThreadsThanFew) {
    const Scene scene = testScene(300);
    const Placement placement = placementFor(scene, Formulation::Robust);
    const auto threadsFor = [&](std::size_t lights) {
        const std::uint64_t before = partThreadsStarted().load();
        EXPECT_TRUE(buildCandidateLists(withLights(scene, lights), placement, FloatWidth::F32, Formulation::Robust, 2));
        return partThreadsStarted().load() - before;
    };
    const std::uint64_t few = threadsFor(4);
    EXPECT_EQ(threadsFor(400), few);
    EXPECT_LE(few, 80u);  // a helper thread per step of the build, whatever the scene
}

TEST(CandidateLists, ALightWhoseListsDoNotFitItsShareTakesTheListOfEverySphere) {
    // The camera looks away from the spheres (its lists take a cell), and the lights' share of
    // the cells is less than a cell per cube face.
    Scene scene = withLights(testScene(200), 3);
    scene.camera.yawDegrees += 180.0;
    const Placement placement = placementFor(scene, Formulation::Robust);
    const auto lists = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust, 2,
                                           CandidateBudget{candidates::kMaxEntries, 18});
    ASSERT_TRUE(lists);
    std::set<std::uint32_t> every;
    for (std::uint32_t node = 0; node < scene.nodes.size(); ++node) {
        if (std::holds_alternative<Sphere>(scene.nodes[node].geometry)) {
            every.insert(node);
        }
    }
    for (std::uint32_t light = 0; light < 3; ++light) {
        for (const glm::vec3 fromLight : {glm::vec3(1, 0.2f, -0.3f), glm::vec3(-0.1f, -1, 0.5f), glm::vec3(0, 0, -1)}) {
            EXPECT_EQ(lightList(*lists, light, fromLight), every) << "light " << light;
        }
        const gpu::GpuCandidateGrid& face = lists->grids.at(1 + gpu::CUBE_FACES * light);
        EXPECT_EQ(face.reach.x, 0.0f);  // every ray is past its reach, and takes the same list
        EXPECT_EQ(face.reach.y, 0.0f);  // in record order
        EXPECT_EQ(face.cells.w, face.cells.z);
    }
}

std::uint32_t listLength(const CandidateLists& lists, std::uint32_t cell) {
    return lists.cellStarts.at(cell + 1) - lists.cellStarts.at(cell);
}

TEST(CandidateLists, ListEverySphereForTextbookShadowRaysPastTheirReach) {
    Scene scene = testScene(200);
    scene.camera.pitchDegrees = 0.0;  // the floor to the horizon: its far points' rays are too long
    const auto lists =
        buildCandidateLists(scene, placementFor(scene, Formulation::Textbook), FloatWidth::F32, Formulation::Textbook);
    ASSERT_TRUE(lists);
    const gpu::GpuCandidateGrid& face = lists->grids.at(1);
    ASSERT_TRUE(std::isfinite(face.reach.x));
    EXPECT_EQ(listLength(*lists, face.cells.w), 200u);
    const auto robust =
        buildCandidateLists(scene, placementFor(scene, Formulation::Robust), FloatWidth::F32, Formulation::Robust);
    ASSERT_TRUE(robust);
    EXPECT_TRUE(std::isinf(robust->grids.at(1).reach.x));  // robust shadow rays start at the light
}

// testScene's view ends at the floor: its shadow rays start where the image's rays meet the floor
// or a sphere. The textbook lists of each cube face hold every ray that looks them up, and no ray
// takes a list of every sphere.
TEST(CandidateLists, TextbookListsHoldEveryShadowRayOfAViewThatEndsAtAPlane) {
    const Scene scene = testScene(200);
    const Placement placement = placementFor(scene, Formulation::Textbook);
    const auto lists = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Textbook);
    ASSERT_TRUE(lists);
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const glm::dvec3 eye = placement.position(scene.camera.position);
    const double floor = placement.position(glm::dvec3(0.0)).y;
    std::vector<glm::dvec3> origins;  // on the floor across the image, and atop each sphere
    for (int i = 0; i <= 16; ++i) {
        for (int j = 0; j <= 16; ++j) {
            const glm::dvec3 direction = sheet.topLeft + i / 16.0 * sheet.right + j / 16.0 * sheet.down;
            ASSERT_LT(direction.y, 0.0) << "the ray must meet the floor";
            origins.push_back(eye + (floor - eye.y) / direction.y * direction);
        }
    }
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            origins.push_back(placement.position(sphere->center + glm::dvec3(0.0, sphere->radius, 0.0)));
        }
    }
    for (std::uint32_t light = 0; light < scene.lights.size(); ++light) {
        const glm::dvec3 position = placement.position(scene.lights[light].position);
        for (const glm::dvec3& origin : origins) {
            const std::uint32_t face = faceOf(origin - position);
            const gpu::GpuCandidateGrid& grid = lists->grids.at(1 + gpu::CUBE_FACES * light + face);
            EXPECT_GE(grid.reach.x, glm::distance(origin, position)) << "light " << light << ", face " << face;
        }
        for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
            const gpu::GpuCandidateGrid& grid = lists->grids.at(1 + gpu::CUBE_FACES * light + face);
            EXPECT_LT(listLength(*lists, grid.cells.w), 200u) << "light " << light << ", face " << face;
        }
    }
}

// Which spheres (node indices) any cell of grid `grid` lists, and how many cells list each.
std::map<std::uint32_t, std::size_t> cellsListing(const CandidateLists& lists, std::uint32_t grid) {
    const gpu::GpuCandidateGrid& g = lists.grids.at(grid);
    std::map<std::uint32_t, std::size_t> cells;
    for (const std::uint32_t cell : cellsOf(g)) {
        for (std::uint32_t k = lists.cellStarts.at(cell); k < lists.cellStarts.at(cell + 1); ++k) {
            ++cells[lists.sphereNodes.at(lists.entries.at(k))];
        }
    }
    return cells;
}

std::size_t cellCount(const CandidateLists& lists, std::uint32_t grid) {
    return std::size_t(lists.grids.at(grid).cells.x) * lists.grids.at(grid).cells.y;
}

// The floor, then the eye looking along +z at a sphere on its left and one on its right, with one
// behind it.
Scene handMadeScene() {
    Scene scene = test::floorSeenFrom({0.0, 2.0, -10.0}, 0.0, 70.0, 320, 180);
    scene.lights = {PointLight{{0.0, 30.0, 20.0}, Color(1.0), 900.0}};
    for (const glm::dvec3& center :
         {glm::dvec3(-8.0, 2.0, 20.0), glm::dvec3(8.0, 2.0, 20.0), glm::dvec3(0.0, 2.0, -30.0)}) {
        scene.nodes.push_back(Node{Sphere{center, 1.0}, 1});
    }
    return scene;
}

TEST(CandidateLists, ListEachSphereOnlyWhereTheEyeCanSeeIt) {
    const Scene scene = handMadeScene();
    const Placement placement = placementFor(scene, Formulation::Robust);
    const auto lists = buildCandidateLists(scene, placement, FloatWidth::F32, Formulation::Robust);
    ASSERT_TRUE(lists);
    const auto towards = [&](std::uint32_t node) {
        return glm::vec3(glm::normalize(std::get<Sphere>(scene.nodes[node].geometry).center - scene.camera.position));
    };
    EXPECT_EQ(cameraList(*lists, towards(1)), std::set<std::uint32_t>{1});
    EXPECT_EQ(cameraList(*lists, towards(2)), std::set<std::uint32_t>{2});
    EXPECT_TRUE(cameraList(*lists, glm::vec3(0.0f, 0.0f, 1.0f)).empty()) << "between the two spheres";
    const std::map<std::uint32_t, std::size_t> listed = cellsListing(*lists, gpu::CAMERA_GRID);
    EXPECT_FALSE(listed.count(3)) << "the sphere behind the eye";
    ASSERT_TRUE(listed.count(1) && listed.count(2));
    // Its outline is about 15 pixels across and the camera's cells start at a pixel: its box's
    // cells, a few hundred, not the window's.
    EXPECT_LT(listed.at(1), 1000u);
    EXPECT_GT(cellCount(*lists, gpu::CAMERA_GRID), 2 * listed.at(1));
}

TEST(CandidateLists, ListASphereAroundTheEyeOrALightOrFillingTheViewInEveryCell) {
    Scene scene = handMadeScene();
    const glm::dvec3 light = scene.lights.at(0).position;
    scene.nodes.push_back(Node{Sphere{scene.camera.position + glm::dvec3(1.0, 0.0, 0.0), 3.0}, 1});  // 4: the eye's
    scene.nodes.push_back(Node{Sphere{light + glm::dvec3(0.0, 0.5, 0.0), 1.0}, 1});                  // 5: the light's
    scene.nodes.push_back(Node{Sphere{{0.0, 2.0, 1e6 + 60.0}, 1e6}, 1});                             // 6: a wall ahead
    for (const Formulation formulation : {Formulation::Robust, Formulation::Textbook}) {
        for (const FloatWidth width : {FloatWidth::F32, FloatWidth::F64}) {
            const auto lists = buildCandidateLists(scene, placementFor(scene, formulation), width, formulation);
            ASSERT_TRUE(lists);
            const std::map<std::uint32_t, std::size_t> camera = cellsListing(*lists, gpu::CAMERA_GRID);
            EXPECT_EQ(camera.at(4), cellCount(*lists, gpu::CAMERA_GRID));
            EXPECT_EQ(camera.at(6), cellCount(*lists, gpu::CAMERA_GRID));
            for (std::uint32_t face = 0; face < gpu::CUBE_FACES; ++face) {
                const std::uint32_t grid = gpu::CAMERA_GRID + 1 + face;  // light 0's faces
                EXPECT_EQ(cellsListing(*lists, grid).at(5), cellCount(*lists, grid)) << "face " << face;
            }
        }
    }
}

}  // namespace
}  // namespace hexray
