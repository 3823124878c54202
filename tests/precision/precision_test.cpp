// Choosing the shader's precision from the scene.

#include <cmath>

#include <gtest/gtest.h>

#include "gpu/render_plan.h"
#include "precision/precision.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

Scene tinySphereAt(double distance) {
    Scene scene;
    scene.shaderNames = {"paper"};
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{Sphere{{0, 0, distance}, 1.0}, 0}};
    return scene;
}

TEST(Precision, NamesRoundTrip) {
    for (Precision p : {Precision::Auto, Precision::F32Naive, Precision::F32, Precision::F64}) {
        EXPECT_EQ(parsePrecision(precisionName(p)), p);
    }
    EXPECT_EQ(parsePrecision("f16"), std::nullopt);
}

TEST(Precision, ConditioningOfTheLectureDemo) {
    // Farthest: the sphere, |(-10, 0, 120)| + 10; smallest feature: its radius 10 (checker 20).
    const Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    const Conditioning c = estimateConditioning(scene);
    EXPECT_NEAR(c.largestDistance, std::sqrt(100.0 + 14400.0) + 10.0, 1e-9);
    EXPECT_EQ(c.smallestFeature, 10.0);
    EXPECT_EQ(choosePrecision(scene, true), Precision::F32);
    // Lengths from the radius 10 to the sphere's far side 130.4: 2^round(log2(sqrt(10 * 130.4))).
    EXPECT_EQ(placementScale(scene), 32.0);
    EXPECT_EQ(sceneMagnitudes(scene).smallest, 10.0);
    EXPECT_NEAR(sceneMagnitudes(scene).largest, std::sqrt(100.0 + 14400.0) + 10.0, 1e-9);
    EXPECT_FALSE(float32RangeProblem(scene));
}

TEST(Precision, ASphereTooSmallForItsDistanceNeedsDouble) {
    EXPECT_EQ(choosePrecision(tinySphereAt(5e3), true), Precision::F32);   // ratio 5e3
    EXPECT_EQ(choosePrecision(tinySphereAt(5e4), true), Precision::F64);   // ratio 5e4
    EXPECT_EQ(choosePrecision(tinySphereAt(5e4), false), Precision::F32);  // the best this device can do
}

TEST(Precision, TheEyeCloseToAHugeSphereNeedsDouble) {
    // Camera 2 above a ground sphere of radius 1e6: the clearance 2 is the smallest feature.
    Scene scene = tinySphereAt(0);
    scene.camera.position = glm::dvec3(0, 2, 0);
    scene.nodes[0].geometry = Sphere{{0, -1e6, 0}, 1e6};
    EXPECT_NEAR(estimateConditioning(scene).smallestFeature, 2.0, 1e-9);
    EXPECT_EQ(choosePrecision(scene, true), Precision::F64);
}

TEST(Precision, AutoPicksFloatForTheCourseScenesAndDoubleForTheHardestCases) {
    for (const char* name :
         {"lecture-demo", "course-2024-lecture4", "spheres-and-lights", "constant-debug", "hard/tiny-sphere-far-1e3",
          "hard/scene-offset-1e7", "hard/checker-far-1e7", "hard/overflow-huge-scale", "hard/underflow-tiny-scale"}) {
        EXPECT_EQ(choosePrecision(loadSceneFile(test::sourcePath(std::string("scenes/") + name + ".json")), true),
                  Precision::F32)
            << name;
    }
    for (const char* name : {"hard/tiny-sphere-far-1e5", "hard/tiny-sphere-far-1e7", "hard/huge-sphere-ground"}) {
        EXPECT_EQ(choosePrecision(loadSceneFile(test::sourcePath(std::string("scenes/") + name + ".json")), true),
                  Precision::F64)
            << name;
    }
}

TEST(Precision, PositionFarFromTheOriginDoesNotMatterOnlyRelativeSize) {
    Scene scene = tinySphereAt(100);
    const double ratioAtOrigin = estimateConditioning(scene).ratio();
    scene.camera.position = glm::dvec3(1e7, -1e7, 1e7);
    scene.nodes[0].geometry = Sphere{glm::dvec3(1e7, -1e7, 1e7 + 100), 1.0};
    EXPECT_NEAR(estimateConditioning(scene).ratio(), ratioAtOrigin, 1e-6);
    EXPECT_EQ(choosePrecision(scene, true), Precision::F32);
}

TEST(Precision, ScaleOfTheSceneDoesNotMatter) {
    Scene small = tinySphereAt(1e-27);
    small.nodes[0].geometry = Sphere{{0, 0, 1e-27}, 1e-30};
    EXPECT_NEAR(estimateConditioning(small).ratio(), 1001.0, 1e-9);
    EXPECT_EQ(choosePrecision(small, true), Precision::F32);
    // The geometric middle of the radius 1e-30 and the far side 1.001e-27.
    EXPECT_EQ(placementScale(small), std::exp2(std::round(0.5 * std::log2(1e-30 * 1.001e-27))));
}

// Issue 12, finding 4: the scale followed the farthest object, so one far out of view pushed
// every visible length toward float's underflow and the light term to inf.
TEST(Precision, AnObjectFarOutOfViewMovesTheScaleByTheSquareRootOfItsDistance) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    scene.nodes.push_back(Node{Sphere{{1e22, 60, 0}, 1.0}, 1});
    EXPECT_EQ(placementScale(scene), std::exp2(std::round(0.5 * std::log2(1e22 + 1.0))));
    EXPECT_FALSE(float32RangeProblem(scene));
    scene.nodes.back() = Node{Sphere{{3.5e38, 60, 0}, 1.0}, 1};
    ASSERT_TRUE(float32RangeProblem(scene));
    EXPECT_EQ(*float32RangeProblem(scene), "its lengths span 1 to 3.5e+38, a ratio beyond float32's 2^100");
    EXPECT_EQ(choosePrecision(scene, true), Precision::F64);
}

}  // namespace
}  // namespace hexray
