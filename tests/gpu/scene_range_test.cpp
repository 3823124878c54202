// No silent wrong image (issue 12, finding 4): scenes at the edges of the supported range
// (docs/scene-format.md, "Supported range") render on the GPU as the CPU reference renders them, and an
// object far out of view changes no visible pixel.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class SceneRangeTest : public test::ValidatedVulkanTest, public ::testing::WithParamInterface<Precision> {};

Scene smallLectureDemo() {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    scene.image.width = 160;
    scene.image.height = 120;
    return scene;
}

// Every length multiplied by `factor`, intensities by its square: the same picture.
Scene scaled(Scene scene, double factor) {
    scene.camera.position *= factor;
    for (PointLight& light : scene.lights) {
        light.position *= factor;
        light.intensity *= factor * factor;
    }
    for (Shader& shader : scene.shaders) {
        if (auto* checker = std::get_if<CheckerShader>(&shader))
            checker->size *= factor;
    }
    for (Node& node : scene.nodes) {
        if (auto* plane = std::get_if<Plane>(&node.geometry))
            plane->height *= factor;
        if (auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            sphere->center *= factor;
            sphere->radius *= factor;
        }
    }
    return scene;
}

// The GPU render agrees with the CPU reference outside ambiguous pixels (compare's defaults), and
// shows something: a frame that is black where the reference is not cannot pass.
void expectAgreement(GpuRenderer& renderer, const Scene& scene, Precision precision) {
    const RenderComparison c = test::compareWithReference(scene, renderer.render(scene, precision));
    EXPECT_LT(c.topology.ambiguousShare(), 0.2);
    EXPECT_EQ(c.topology.mismatches, 0u);
    EXPECT_LE(c.encoded.rmse, Tolerance{}.maxRmseLevels);
    EXPECT_LE(c.linear.maxAbs, 0.01);
}

// 1e22 and 3.5e38 away along +x: 90 degrees off the view axis, outside the 90-degree diagonal
// field. The first burned the lit floor white in every precision (the light term overflowed), the
// second turned the frame black; float32 cannot hold the second (a ratio of lengths beyond 2^100),
// which `render` then says before rendering in f64 (cli_test.cpp).
TEST_P(SceneRangeTest, OutOfViewSphereFarAwayChangesNoVisiblePixel) {
    const Scene demo = smallLectureDemo();
    GpuRenderer renderer(context());
    for (const double distance : {1e22, 3.5e38}) {
        SCOPED_TRACE(distance);
        Scene withFarSphere = demo;
        withFarSphere.nodes.push_back(Node{Sphere{{distance, 60, 0}, 1.0}, 1});
        const bool float32CannotHold = float32RangeProblem(withFarSphere).has_value();
        EXPECT_EQ(float32CannotHold, distance > 1e30);
        if (GetParam() == Precision::F32 && float32CannotHold) {
            continue;
        }
        const GpuRenderResult far = renderer.render(withFarSphere, GetParam());
        // In the precision the far sphere's scene rendered in (auto may pick f64 for it).
        const GpuRenderResult alone = renderer.render(demo, far.precision);
        EXPECT_EQ(far.classes, alone.classes);
        float largest = 0.0f;
        for (std::size_t i = 0; i < alone.image.pixels.size(); ++i) {
            for (int channel = 0; channel < 3; ++channel) {
                largest = std::max(largest, std::abs(far.image.pixels[i][channel] - alone.image.pixels[i][channel]));
            }
        }
        EXPECT_LE(largest, 1e-6f);
        expectAgreement(renderer, withFarSphere, GetParam());
    }
}

// A sphere centred 3.5e38 away, lit from beside the eye: every length is near float's limit.
TEST_P(SceneRangeTest, SphereCentredAt3point5e38MatchesTheReference) {
    Scene scene;
    scene.image.width = 64;
    scene.image.height = 48;
    scene.ambient = Color(0.1);
    scene.background = Color(0.0, 0.0, 0.3);
    scene.camera.fovDegrees = 60.0;
    scene.shaders.push_back(LambertShader{{0.8, 0.5, 0.0}});
    scene.nodes.push_back(Node{Sphere{{0.0, 0.0, 3.5e38}, 1e38}, 0});
    scene.lights.push_back(PointLight{{0.0, 2e38, 0.0}, Color(1.0), 1e77});
    GpuRenderer renderer(context());
    expectAgreement(renderer, scene, GetParam());
}

// The lecture's scene scaled to the largest and the smallest lengths the loader accepts.
TEST_P(SceneRangeTest, LectureSceneAtTheEdgesOfTheSupportedRange) {
    GpuRenderer renderer(context());
    for (const double factor : {5e47, 1e-51}) {
        SCOPED_TRACE(factor);
        expectAgreement(renderer, scaled(smallLectureDemo(), factor), GetParam());
    }
}

INSTANTIATE_TEST_SUITE_P(Precisions, SceneRangeTest, ::testing::Values(Precision::F32, Precision::F64, Precision::Auto),
                         [](const auto& info) {
                             return std::string(info.param == Precision::F32   ? "f32"
                                                : info.param == Precision::F64 ? "f64"
                                                                               : "auto");
                         });

}  // namespace
}  // namespace hexray
