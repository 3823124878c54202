// The candidate lists (shaders/candidates.glsl) must not change what any pixel shows: a scene
// traced through them and through every node in turn gives the same image, classes and AOVs bit
// for bit, in every precision, also where spheres are far smaller than a pixel, straddle the eye's
// plane or a light's cube faces, or hold the eye or a light; and it agrees with the CPU reference.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "camera/camera.h"
#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/random_spheres.h"
#include "support/floor_scene.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"
#include "support/random_uniform.h"

namespace hexray {
namespace {

using GpuCandidatesTest = test::PrecisionVulkanTest;

using test::uniform;

Scene randomScene(std::uint32_t spheres, std::uint64_t seed) {
    Scene scene = makeRandomSpheresScene(spheres, seed);
    scene.image.width = 160;
    scene.image.height = 90;
    return scene;
}

// A floor to the horizon, seen from just above; spheres far below a pixel's size far out, spheres
// beside and behind the eye across its plane, spheres on the diagonals between a light's cube
// faces, a light inside a sphere and one among small spheres.
Scene edgeCaseScene() {
    Scene scene = test::floorSeenFrom({0.0, 2.0, -10.0}, 0.0, 70.0, 192, 108);
    scene.lights = {PointLight{{0.0, 30.0, 20.0}, Color(1.0), 900.0}, PointLight{{-5.0, 3.5, 8.0}, Color(1.0), 50.0},
                    PointLight{{4.0, 1.0, 5.0}, Color(0.5), 40.0}};
    std::mt19937_64 engine(17);
    const auto add = [&](glm::dvec3 center, double radius) {
        scene.nodes.push_back(Node{Sphere{center, radius}, 1 + std::uint32_t(scene.nodes.size() % 5)});
    };
    for (int i = 0; i < 1500; ++i) {  // about a hundredth of a pixel to a few pixels across
        const double distance = uniform(engine, 15.0, 300.0);
        add({uniform(engine, -0.6, 0.6) * distance, uniform(engine, 0.0, 0.4) * distance, distance - 10.0},
            distance * std::exp(uniform(engine, std::log(3e-5), std::log(1e-2))));
    }
    add({-5.0, 3.0, 8.0}, 2.0);  // holds the second light
    for (int i = 0; i < 60; ++i) {
        add({4.0 + uniform(engine, -2, 2), uniform(engine, 0.1, 2.5), 5.0 + uniform(engine, -2, 2)},
            uniform(engine, 0.05, 0.4));
    }
    for (int i = 0; i < 40; ++i) {  // on the first light's face diagonals, near and far
        const double d = uniform(engine, 2.0, 25.0);
        const double sx = i % 2 ? 1.0 : -1.0;
        const double sz = i % 4 < 2 ? 1.0 : -1.0;
        add({sx * d, 30.0 - d, 20.0 + sz * d}, uniform(engine, 0.1, 1.0));
    }
    add({3.0, 2.0, -10.0}, 1.5);   // across the eye's plane, beside it
    add({-2.0, 1.0, -14.0}, 1.0);  // behind the eye
    add({0.0, 2.0, -10.3}, 0.29);  // just behind the eye, nearly touching it
    return scene;
}

// A floor to the horizon and a light in a cloud of spheres: f32-naive shadow rays from the far
// floor (the rows next to the horizon lie tens of thousands of units out) are longer than the
// light's lists hold (their rounding grows with their length) and take the list of every sphere.
Scene horizonScene() {
    Scene scene = test::floorSeenFrom({0.0, 100.0, -300.0}, -5.0, 60.0, 192, 108);
    scene.lights = {PointLight{{0.0, 100.0, 0.0}, Color(1.0), 40000.0}};
    std::mt19937_64 engine(29);
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 center(uniform(engine, -40, 40), uniform(engine, 60, 140), uniform(engine, -40, 40));
        if (glm::distance(center, scene.lights[0].position) > 8.0) {
            scene.nodes.push_back(Node{Sphere{center, uniform(engine, 0.5, 3.0)}, 1 + std::uint32_t(i % 5)});
        }
    }
    return scene;
}

// Spheres far smaller than the textbook test's rounding, a thousand units out, through a narrow
// view: f32-naive's b^2 - 4ac cancels, and reports camera rays that miss a sphere by tenths of a
// unit (up to about sqrt(16 u) |f|) as hitting it. The lists must hold each sphere that far out.
Scene roundingBandScene() {
    Scene scene = test::floorSeenFrom({3.0, 2.0, -10.0}, 0.0, 3.0, 192, 108);
    scene.lights = {PointLight{{3.0, 40.0, 900.0}, Color(1.0), 20000.0}};
    for (int x = -22; x <= 22; ++x) {
        for (int y = 1; y <= 13; ++y) {
            scene.nodes.push_back(Node{Sphere{{3.0 + x, double(y), 1000.0 + 0.5 * (x % 3)}, 1e-3}, 1});
        }
    }
    return scene;
}

// The eye inside a large sphere with a light and spheres inside it too.
Scene insideScene() {
    Scene scene = makeRandomSpheresScene(300, 23);
    scene.image.width = 128;
    scene.image.height = 72;
    scene.nodes.push_back(Node{Sphere{scene.camera.position + glm::dvec3(0, 0, 20), 200.0}, 2});
    scene.lights.push_back(PointLight{scene.camera.position + glm::dvec3(5, 5, 30), Color(1.0), 2000.0});
    return scene;
}

// Pairs of spheres whose near points coincide on a pixel's ray: one centred on the ray, and a
// larger one centred further along it, through the first one's near point; the first ones take
// the lower node indices. The two hits tie to within rounding, and each sphere's depth (the camera
// lists' depth order) equals the other's hit distance: a list that stopped at the second of the
// pair without the depth margin (shader_interface.h's DEPTH_ORDER_UNITS) loses the pixels where
// that one's own test wins the tie (10 pixels in f32 and 6 in f64 with a margin of 0).
Scene tiedPairsScene() {
    Scene scene = makeRandomSpheresScene(40, 31);
    scene.image.width = 128;
    scene.image.height = 72;
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    std::vector<Node> onTheRay;
    std::vector<Node> behind;
    for (std::uint32_t y = 1; y < scene.image.height; y += 3) {
        for (std::uint32_t x = 1; x < scene.image.width; x += 3) {
            const glm::dvec3 direction = sampleDirection(sheet, scene.image, x, y, 0);
            const double distance = 30.0 + 0.37 * x + 0.11 * y;
            const double radius = 0.2 + 0.01 * (x % 7);
            const glm::dvec3 nearPoint = sheet.origin + (distance - radius) * direction;
            onTheRay.push_back(Node{Sphere{sheet.origin + distance * direction, radius}, 1});
            behind.push_back(Node{Sphere{nearPoint + 1.5 * radius * direction, 1.5 * radius}, 2});
        }
    }
    scene.nodes.insert(scene.nodes.begin() + 1, onTheRay.begin(), onTheRay.end());  // after the floor
    scene.nodes.insert(scene.nodes.end(), behind.begin(), behind.end());
    return scene;
}

// Spheres in front of a huge one that fills most of the view, and a huge one under the floor whose
// top pokes through it.
Scene hugeScene() {
    Scene scene = makeRandomSpheresScene(300, 29);
    scene.image.width = 128;
    scene.image.height = 72;
    const glm::dvec3 forward = cameraForward(scene.camera);
    double farthest = 0.0;
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            farthest = std::max(farthest, glm::distance(sphere->center, scene.camera.position) + sphere->radius);
        }
    }
    scene.nodes.push_back(Node{Sphere{scene.camera.position + forward * (farthest + 1e6), 1e6}, 4});
    scene.nodes.push_back(Node{Sphere{{0.0, -1e5 + 0.5, farthest / 2}, 1e5}, 3});
    return scene;
}

// A few spheres on a floor under a few thousand lights: each light has its own lists, built on a
// thread per core. (Kept to what lavapipe runs in one dispatch, testing every node too: past its
// loop limit both would render in light batches, light_batches_test.cpp's subject.)
Scene manyLightsScene() {
    Scene scene = makeRandomSpheresScene(24, 5);
    scene.image.width = 64;
    scene.image.height = 36;
    std::mt19937_64 engine(41);
    const double side = 4.0 * std::sqrt(24.0) + 10.0;
    scene.lights.clear();
    for (int i = 0; i < 1500; ++i) {
        const glm::dvec3 position(uniform(engine, -0.5, 0.5) * side, uniform(engine, 3.0, 20.0),
                                  uniform(engine, 0.0, 1.0) * side);
        scene.lights.push_back(PointLight{position, Color(1.0), 0.4 * side * side / 1500.0});
    }
    return scene;
}

void expectSameAsEveryNode(GpuRenderer& renderer, const Scene& scene, Precision precision) {
    const GpuRenderResult every = renderer.render(scene, precision, GpuOutput::LinearClassesAndAov, Acceleration::None);
    const GpuRenderResult listed =
        renderer.render(scene, precision, GpuOutput::LinearClassesAndAov, Acceleration::Always);
    ASSERT_FALSE(every.usedCandidateLists);
    ASSERT_TRUE(listed.usedCandidateLists);
    std::size_t differentPixels = 0;
    std::size_t differentClasses = 0;
    std::size_t differentAovs = 0;
    std::size_t spheres = 0;
    for (std::size_t i = 0; i < every.classes.size(); ++i) {
        differentPixels += every.image.pixels[i] != listed.image.pixels[i];
        differentClasses += every.classes[i] != listed.classes[i];
        const bool sameDepth =
            std::bit_cast<std::uint32_t>(every.depth[i]) == std::bit_cast<std::uint32_t>(listed.depth[i]);
        differentAovs += !sameDepth || every.normals[i] != listed.normals[i];
        spheres += every.classes[i].node != PixelClass::kBackground && every.classes[i].node > 0;
    }
    EXPECT_EQ(differentPixels, 0u);
    EXPECT_EQ(differentClasses, 0u);
    EXPECT_EQ(differentAovs, 0u);
    EXPECT_GT(spheres, every.classes.size() / 20) << "the scene must show spheres to test anything";
}

TEST_P(GpuCandidatesTest, GiveTheSameImageClassesAndAovsAsTestingEveryNode) {
    GpuRenderer renderer(context());
    for (const std::uint32_t spheres : {40u, 700u, 5000u}) {
        SCOPED_TRACE(std::to_string(spheres) + " spheres");
        expectSameAsEveryNode(renderer, randomScene(spheres, spheres), GetParam());
    }
}

TEST_P(GpuCandidatesTest, GiveTheSameImageAtTheEdgeCases) {
    GpuRenderer renderer(context());
    {
        SCOPED_TRACE("tiny spheres, the eye's plane, cube face edges, lights among spheres");
        expectSameAsEveryNode(renderer, edgeCaseScene(), GetParam());
    }
    if (GetParam() == Precision::F32Naive) {  // the robust tests report none of these spheres
        SCOPED_TRACE("spheres within the textbook test's rounding");
        expectSameAsEveryNode(renderer, roundingBandScene(), GetParam());
    }
    {
        SCOPED_TRACE("the far floor's shadow rays");
        expectSameAsEveryNode(renderer, horizonScene(), GetParam());
    }
    {
        SCOPED_TRACE("the eye inside a sphere");
        expectSameAsEveryNode(renderer, insideScene(), GetParam());
    }
    {
        SCOPED_TRACE("huge spheres");
        expectSameAsEveryNode(renderer, hugeScene(), GetParam());
    }
    {
        SCOPED_TRACE("many lights");
        expectSameAsEveryNode(renderer, manyLightsScene(), GetParam());
    }
    {
        SCOPED_TRACE("spheres whose near points tie on a pixel's ray");
        expectSameAsEveryNode(renderer, tiedPairsScene(), GetParam());
    }
}

// f32-naive is left out: it disagrees with the reference (shadow acne) with or without lists.
class GpuCandidatesAgreementTest : public GpuCandidatesTest {};

// Random spheres take the fast camera and shadow tests (RenderPlan::fastCameraTests and
// fastShadowTests); with a sphere whose surface passes a tenth of its radius from the eye, or from
// a light, every sphere takes the robust one from there.
TEST_P(GpuCandidatesAgreementTest, AgreeWithTheCpuReference) {
    GpuRenderer renderer(context());
    for (const std::uint32_t spheres : {100u, 2000u, 20000u, 0u, 1u}) {
        const bool nextToEye = spheres == 0;
        const bool nextToLight = spheres == 1;
        SCOPED_TRACE(nextToEye     ? "a sphere next to the eye"
                     : nextToLight ? "a sphere next to a light"
                                   : std::to_string(spheres) + " spheres");
        Scene scene = randomScene(nextToEye || nextToLight ? 2000u : spheres, 11);
        if (nextToEye) {
            const glm::dvec3 aside = glm::cross(cameraForward(scene.camera), glm::dvec3(0, 1, 0));
            scene.nodes.push_back(Node{Sphere{scene.camera.position + 11.0 * glm::normalize(aside), 10.0}, 2});
        }
        if (nextToLight) {
            scene.nodes.push_back(Node{Sphere{scene.lights[0].position + glm::dvec3(0, 11, 0), 10.0}, 2});
        }
        const GpuRenderResult gpu = renderer.render(scene, GetParam());
        ASSERT_TRUE(gpu.usedCandidateLists) << "Auto must choose the lists past a generated kernel";
        const RenderComparison c = test::compareWithReference(scene, gpu);
        const Tolerance tolerance;
        EXPECT_LE(c.topology.ambiguousShare(), 0.2);
        EXPECT_EQ(c.topology.mismatches, 0u);
        EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent);
        EXPECT_LE(c.encoded.rmse, tolerance.maxRmseLevels);
    }
}

TEST_P(GpuCandidatesAgreementTest, AgreeWithTheCpuReferenceUnderManyLights) {
    GpuRenderer renderer(context());
    const Scene scene = manyLightsScene();
    const GpuRenderResult gpu = renderer.render(scene, GetParam());
    ASSERT_TRUE(gpu.usedCandidateLists);
    const RenderComparison c = test::compareWithReference(scene, gpu);
    const Tolerance tolerance;
    // With a light's terminator or grazing shadow for every 1500th of the lights, many pixels hold
    // a near-tie; half of them or more are still compared.
    EXPECT_LE(c.topology.ambiguousShare(), 0.5);
    EXPECT_EQ(c.topology.mismatches, 0u);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, tolerance.maxRmseLevels);
}

class GpuCandidatesChoiceTest : public test::ValidatedVulkanTest {};

TEST_F(GpuCandidatesChoiceTest, SmallScenesKeepTheGeneratedKernels) {
    GpuRenderer renderer(context());
    EXPECT_FALSE(renderer.render(randomScene(20, 3)).usedCandidateLists);
    EXPECT_TRUE(renderer.render(randomScene(40, 3)).usedCandidateLists);
}

std::string precisionTestName(const ::testing::TestParamInfo<Precision>& info) {
    std::string name(precisionName(info.param));
    std::erase(name, '-');  // test names allow only letters, digits and _
    return name;
}

INSTANTIATE_TEST_SUITE_P(Precisions, GpuCandidatesTest,
                         ::testing::Values(Precision::F32, Precision::F64, Precision::F32Naive), precisionTestName);
INSTANTIATE_TEST_SUITE_P(Precisions, GpuCandidatesAgreementTest, ::testing::Values(Precision::F32, Precision::F64),
                         precisionTestName);

}  // namespace
}  // namespace hexray
