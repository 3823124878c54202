// The BVH over spheres: its structure, and that the CPU reference gives the same answers, bit
// for bit, with and without it.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "accel/bvh.h"
#include "cpu/cpu_intersect.h"
#include "cpu/cpu_renderer.h"
#include "cpu/cpu_shading.h"
#include "scene/random_spheres.h"

using namespace hexray;

namespace {

double uniform01(std::mt19937_64& engine) {
    return double(engine() >> 11) * 0x1.0p-53;
}

double uniform(std::mt19937_64& engine, double low, double high) {
    return low + (high - low) * uniform01(engine);
}

glm::dvec3 randomUnitVector(std::mt19937_64& engine) {
    for (;;) {
        const glm::dvec3 v(uniform(engine, -1, 1), uniform(engine, -1, 1), uniform(engine, -1, 1));
        const double length = glm::length(v);
        if (length > 0.1 && length <= 1.0) {
            return v / length;
        }
    }
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool contains(const BvhNode& outer, const glm::dvec3& min, const glm::dvec3& max) {
    return glm::all(glm::lessThanEqual(outer.boundsMin, min)) && glm::all(glm::lessThanEqual(max, outer.boundsMax));
}

// Walks the tree checking bounds and collecting the leaf ranges; returns the subtree's end.
std::uint32_t checkSubtree(const Scene& scene, const Bvh& bvh, std::uint32_t index, std::vector<int>& seen) {
    const BvhNode& node = bvh.nodes.at(index);
    if (node.isLeaf()) {
        EXPECT_LE(node.count, kMaxBvhLeafSpheres);
        for (std::uint32_t i = 0; i < node.count; ++i) {
            const std::uint32_t sceneNode = bvh.sphereNodes.at(node.firstOrSecondChild + i);
            ++seen.at(node.firstOrSecondChild + i);
            const Sphere& sphere = std::get<Sphere>(scene.nodes.at(sceneNode).geometry);
            EXPECT_TRUE(contains(node, sphere.center - sphere.radius, sphere.center + sphere.radius))
                << "node " << index << " sphere " << sceneNode;
        }
        return index + 1;
    }
    const std::uint32_t first = index + 1;
    const std::uint32_t second = node.firstOrSecondChild;
    EXPECT_TRUE(contains(node, bvh.nodes.at(first).boundsMin, bvh.nodes.at(first).boundsMax)) << index;
    EXPECT_TRUE(contains(node, bvh.nodes.at(second).boundsMin, bvh.nodes.at(second).boundsMax)) << index;
    const std::uint32_t firstEnd = checkSubtree(scene, bvh, first, seen);
    EXPECT_EQ(firstEnd, second) << "depth-first layout: the second child follows the first's subtree";
    return checkSubtree(scene, bvh, second, seen);
}

void expectSameHit(const std::optional<SceneHit>& expected, const std::optional<SceneHit>& actual, const Ray& ray) {
    ASSERT_EQ(expected.has_value(), actual.has_value())
        << "ray from (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ")";
    if (expected) {
        EXPECT_EQ(expected->nodeIndex, actual->nodeIndex);
        EXPECT_TRUE(sameBits(expected->hit.t, actual->hit.t)) << expected->hit.t << " vs " << actual->hit.t;
    }
}

// A scene's camera rays, rays from random points toward sphere centres and edges, and rays in
// random directions; nearest hits and shadow segments against the brute-force loop.
void expectBvhAgrees(const Scene& scene, std::uint32_t rayCount, std::uint64_t seed) {
    const Bvh bvh = buildBvh(scene);
    std::mt19937_64 engine(seed);
    std::vector<const Sphere*> spheres;
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            spheres.push_back(sphere);
        }
    }
    const glm::dvec3 low = bvh.nodes.at(0).boundsMin;
    const glm::dvec3 high = bvh.nodes.at(0).boundsMax;
    int hits = 0;
    for (std::uint32_t i = 0; i < rayCount; ++i) {
        glm::dvec3 origin;
        switch (i % 3) {
            case 0:
                origin = scene.camera.position;
                break;
            case 1:
                origin = {uniform(engine, low.x, high.x), uniform(engine, 0.01, high.y),
                          uniform(engine, low.z, high.z)};
                break;
            default:
                origin = spheres[engine() % spheres.size()]->center;
                break;  // inside a sphere
        }
        glm::dvec3 direction;
        if (i % 2 == 0) {
            // At a sphere: its centre, or a point on it (grazing and tangent rays).
            const Sphere& target = *spheres[engine() % spheres.size()];
            const glm::dvec3 aim =
                (i % 4 == 0) ? target.center : target.center + target.radius * randomUnitVector(engine);
            direction = aim - origin;
            if (glm::length(direction) == 0.0) {
                direction = randomUnitVector(engine);
            }
            direction = glm::normalize(direction);
        } else {
            direction = randomUnitVector(engine);
        }
        const Ray ray{origin, direction};
        const std::optional<SceneHit> brute = findNearestHit(ray, scene);
        const std::optional<SceneHit> accelerated = findNearestHit(ray, scene, &bvh);
        expectSameHit(brute, accelerated, ray);
        hits += brute.has_value();

        // Shadow segments: to the nearest hit (ties with the end), a little before and after it,
        // and to random points.
        for (const double maxT : {brute ? brute->hit.t : 1.0, brute ? std::nextafter(brute->hit.t, 0.0) : 5.0,
                                  brute ? std::nextafter(brute->hit.t, 1e300) : 50.0, uniform(engine, 0.0, 100.0)}) {
            EXPECT_EQ(hasSphereHitBefore(ray, scene, maxT), hasSphereHitBefore(ray, scene, maxT, &bvh)) << maxT;
        }
        const glm::dvec3 to = origin + uniform(engine, 0.0, 2.0 * glm::length(high - low)) * direction;
        EXPECT_EQ(isSegmentClear(scene, origin, to, 1e-9), isSegmentClear(scene, origin, to, 1e-9, &bvh));
    }
    EXPECT_GT(hits, int(rayCount) / 4) << "too few rays hit anything to test much";
}

}  // namespace

TEST(Bvh, EverySphereIsInExactlyOneLeafAndBoundsNest) {
    for (const std::uint32_t count : {1u, 2u, 5u, 17u, 100u, 1000u}) {
        Scene scene = makeRandomSpheresScene(count, 7);
        scene.nodes.push_back(Node{Plane{-3.0}, 0});  // planes stay out of it, wherever they are
        const Bvh bvh = buildBvh(scene);
        ASSERT_EQ(bvh.sphereNodes.size(), count);
        std::vector<int> timesInScene(scene.nodes.size(), 0);
        for (const std::uint32_t sceneNode : bvh.sphereNodes) {
            ASSERT_LT(sceneNode, scene.nodes.size());
            EXPECT_TRUE(std::holds_alternative<Sphere>(scene.nodes[sceneNode].geometry));
            ++timesInScene[sceneNode];
        }
        for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
            const bool isSphere = std::holds_alternative<Sphere>(scene.nodes[index].geometry);
            EXPECT_EQ(timesInScene[index], isSphere ? 1 : 0) << "node " << index;
        }
        std::vector<int> slotSeen(bvh.sphereNodes.size(), 0);
        EXPECT_EQ(checkSubtree(scene, bvh, 0, slotSeen), bvh.nodes.size()) << "every node reachable once";
        for (std::size_t slot = 0; slot < slotSeen.size(); ++slot) {
            EXPECT_EQ(slotSeen[slot], 1) << "slot " << slot << " of sphereNodes in exactly one leaf";
        }
    }
}

TEST(Bvh, IsDeterministic) {
    const Scene scene = makeRandomSpheresScene(2000, 3);
    const Bvh a = buildBvh(scene);
    const Bvh b = buildBvh(makeRandomSpheresScene(2000, 3));
    EXPECT_EQ(a.sphereNodes, b.sphereNodes);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)));
}

// Large trees are built by several threads, each taking whichever subtree is next; which thread
// built what must not show in the tree. Enough spheres that the work is split many times.
TEST(Bvh, SameTreeOnAnyNumberOfThreads) {
    const Scene scene = makeRandomSpheresScene(200000, 5);
    const Bvh reference = buildBvh(scene, 1);
    std::vector<int> slotSeen(reference.sphereNodes.size(), 0);
    EXPECT_EQ(checkSubtree(scene, reference, 0, slotSeen), reference.nodes.size());
    EXPECT_TRUE(std::all_of(slotSeen.begin(), slotSeen.end(), [](int seen) { return seen == 1; }));
    for (const unsigned threads : {2u, 3u, 8u}) {
        SCOPED_TRACE(testing::Message() << threads << " threads");
        const Bvh bvh = buildBvh(scene, threads);
        EXPECT_EQ(bvh.sphereNodes, reference.sphereNodes);
        EXPECT_EQ(bvh.planeNodes, reference.planeNodes);
        ASSERT_EQ(bvh.nodes.size(), reference.nodes.size());
        EXPECT_EQ(0, std::memcmp(bvh.nodes.data(), reference.nodes.data(), bvh.nodes.size() * sizeof(BvhNode)));
    }
}

TEST(Bvh, EmptyAndPlaneOnlyScenesHaveNoNodes) {
    Scene scene;
    EXPECT_TRUE(buildBvh(scene).nodes.empty());
    scene.nodes.push_back(Node{Plane{0.0}, 0});
    const Bvh bvh = buildBvh(scene);
    EXPECT_TRUE(bvh.nodes.empty());
    const Ray down{{0, 1, 0}, {0, -1, 0}};
    expectSameHit(findNearestHit(down, scene), findNearestHit(down, scene, &bvh), down);
}

TEST(Bvh, IdenticalSpheresInOneLeafStillSplit) {
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    for (int i = 0; i < 40; ++i) {
        scene.nodes.push_back(Node{Sphere{{1, 2, 3}, 1.0}, 0});
    }
    const Bvh bvh = buildBvh(scene);
    std::vector<int> slotSeen(bvh.sphereNodes.size(), 0);
    checkSubtree(scene, bvh, 0, slotSeen);
    const Ray ray{{1, 2, -10}, {0, 0, 1}};
    const std::optional<SceneHit> hit = findNearestHit(ray, scene, &bvh);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->nodeIndex, 0u);
}

TEST(Bvh, RandomScenesMatchTheBruteForceLoop) {
    for (const std::uint32_t count : {1u, 10u, 100u, 1000u, 10000u}) {
        SCOPED_TRACE(testing::Message() << count << " spheres");
        expectBvhAgrees(makeRandomSpheresScene(count, 1000 + count), count >= 10000 ? 1500 : 3000, count);
    }
}

TEST(Bvh, ExactTiesGoToTheEarlierNode) {
    // Copies of spheres, before and after the originals: every copy ties its original exactly.
    Scene scene = makeRandomSpheresScene(300, 11);
    const std::size_t originals = scene.nodes.size();
    // Later twins: copies appended at the end.
    for (std::size_t index = 1; index < originals; index += 3) {
        scene.nodes.push_back(scene.nodes[index]);  // a later twin
    }
    // Earlier twins: prepend copies of some spheres right after the floor.
    std::vector<Node> earlier;
    for (std::size_t index = 2; index < originals; index += 5) {
        earlier.push_back(scene.nodes[index]);
    }
    scene.nodes.insert(scene.nodes.begin() + 1, earlier.begin(), earlier.end());
    const Bvh bvh = buildBvh(scene);

    int ties = 0;
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        const auto* sphere = std::get_if<Sphere>(&scene.nodes[index].geometry);
        if (!sphere) {
            continue;
        }
        const Ray ray{scene.camera.position, glm::normalize(sphere->center - scene.camera.position)};
        const std::optional<SceneHit> brute = findNearestHit(ray, scene);
        const std::optional<SceneHit> accelerated = findNearestHit(ray, scene, &bvh);
        expectSameHit(brute, accelerated, ray);
        if (!brute) {
            continue;
        }
        // Is the winner one of a set of identical spheres? Then it must be the first of them.
        const Geometry& winner = scene.nodes[brute->nodeIndex].geometry;
        if (const auto* winnerSphere = std::get_if<Sphere>(&winner)) {
            for (std::size_t other = 0; other < scene.nodes.size(); ++other) {
                const auto* twin = std::get_if<Sphere>(&scene.nodes[other].geometry);
                if (other != brute->nodeIndex && twin && twin->center == winnerSphere->center &&
                    twin->radius == winnerSphere->radius) {
                    ++ties;
                    EXPECT_GT(other, brute->nodeIndex) << "an identical earlier sphere should have won";
                }
            }
        }
    }
    EXPECT_GT(ties, 20);
}

TEST(Bvh, RenderIsBitIdenticalWithAndWithout) {
    const Scene scene = makeRandomSpheresScene(200, 42);
    const CpuRender plain = renderOnCpu(scene, 0, Acceleration::None);
    const CpuRender accelerated = renderOnCpu(scene, 0, Acceleration::Always);
    ASSERT_EQ(plain.image.pixels.size(), accelerated.image.pixels.size());
    EXPECT_EQ(0, std::memcmp(plain.image.pixels.data(), accelerated.image.pixels.data(),
                             plain.image.pixels.size() * sizeof(glm::vec3)));
    EXPECT_EQ(plain.classes, accelerated.classes);
    ASSERT_EQ(plain.margins.size(), accelerated.margins.size());
    EXPECT_EQ(0, std::memcmp(plain.margins.data(), accelerated.margins.data(), plain.margins.size() * sizeof(float)));
    EXPECT_EQ(plain.ambiguity, accelerated.ambiguity);
    std::size_t spherePixels = 0;
    std::size_t ambiguous = 0;
    for (std::size_t pixel = 0; pixel < plain.classes.size(); ++pixel) {
        spherePixels += plain.classes[pixel].node != PixelClass::kBackground && plain.classes[pixel].node != 0;
        ambiguous += plain.isAmbiguous(pixel);
    }
    EXPECT_GT(spherePixels, plain.classes.size() / 10) << "the camera should see the spheres";
    EXPECT_GT(ambiguous, 0u) << "some close calls, so the margins were put to the test";
}

TEST(Bvh, MarginsAreBitIdenticalWhereNearMissesDecideThem) {
    // Constant shaders and no floor: a pixel's margin is its nearest near miss or hit/hit gap,
    // exactly what the BVH's margin pass prunes by.
    Scene scene = makeRandomSpheresScene(500, 5);
    scene.nodes.erase(scene.nodes.begin());
    for (Shader& shader : scene.shaders) {
        shader = ConstantShader{};
    }
    scene.image.width = 200;
    scene.image.height = 120;
    const CpuRender plain = renderOnCpu(scene, 0, Acceleration::None);
    const CpuRender accelerated = renderOnCpu(scene, 0, Acceleration::Always);
    EXPECT_EQ(plain.classes, accelerated.classes);
    ASSERT_EQ(plain.margins.size(), accelerated.margins.size());
    std::size_t different = 0;
    for (std::size_t pixel = 0; pixel < plain.margins.size(); ++pixel) {
        different += std::bit_cast<std::uint32_t>(plain.margins[pixel]) !=
                     std::bit_cast<std::uint32_t>(accelerated.margins[pixel]);
    }
    EXPECT_EQ(different, 0u);
    EXPECT_EQ(plain.ambiguity, accelerated.ambiguity);
}

TEST(Bvh, PaysOnlyForManySpheres) {
    EXPECT_FALSE(bvhPays(makeRandomSpheresScene(kBvhMinSpheres, 1)));
    EXPECT_TRUE(bvhPays(makeRandomSpheresScene(kBvhMinSpheres + 1, 1)));
}

TEST(RandomSpheresScene, IsDeterministicAndAsAsked) {
    const Scene a = makeRandomSpheresScene(50, 9);
    const Scene b = makeRandomSpheresScene(50, 9);
    const Scene c = makeRandomSpheresScene(50, 10);
    ASSERT_EQ(a.nodes.size(), 51u);
    EXPECT_EQ(countSpheres(a), 50u);
    EXPECT_EQ(a.image.width, 320u);
    EXPECT_EQ(a.image.height, 180u);
    bool anyDifferent = false;
    for (std::size_t index = 1; index < a.nodes.size(); ++index) {
        const Sphere& sa = std::get<Sphere>(a.nodes[index].geometry);
        const Sphere& sb = std::get<Sphere>(b.nodes[index].geometry);
        const Sphere& sc = std::get<Sphere>(c.nodes[index].geometry);
        EXPECT_EQ(sa.center, sb.center);
        EXPECT_EQ(sa.radius, sb.radius);
        EXPECT_EQ(a.nodes[index].shaderIndex, b.nodes[index].shaderIndex);
        EXPECT_LT(a.nodes[index].shaderIndex, a.shaders.size());
        EXPECT_GT(sa.radius, 0.0);
        anyDifferent |= sa.center != sc.center;
    }
    EXPECT_TRUE(anyDifferent);
}
