// The GPU renderer on small scenes whose pixels are known by hand.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "gpu/gpu_scene.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

using GpuRendererTest = test::ValidatedVulkanTest;

Scene smallScene(std::uint32_t width, std::uint32_t height) {
    Scene scene;
    scene.image.width = width;
    scene.image.height = height;
    return scene;
}

// Camera at `eye` looking straight down; the centre pixel of an odd-sized image looks at (x, 0, z).
Scene lookingDownAtPlane(const glm::dvec3& eye) {
    Scene scene = smallScene(9, 9);
    scene.camera.position = eye;
    scene.camera.pitchDegrees = -90;
    scene.ambient = Color(0.1);
    scene.shaderNames = {"paper"};
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{Plane{0.0}, 0}};
    return scene;
}

TEST_F(GpuRendererTest, EmptySceneIsBackgroundEverywhere) {
    Scene scene = smallScene(17, 13);
    scene.background = Color(0.25, 0.5, 0.75);
    GpuRenderer renderer(context());
    const Image image = renderer.render(scene).image;
    ASSERT_EQ(image.pixels.size(), 17u * 13u);
    for (const glm::vec3& pixel : image.pixels) {
        EXPECT_EQ(pixel, glm::vec3(0.25f, 0.5f, 0.75f));
    }
}

TEST_F(GpuRendererTest, ConstantSphereAroundTheCameraFillsTheView) {
    Scene scene = smallScene(16, 8);
    scene.shaderNames = {"flat"};
    scene.shaders = {ConstantShader{Color(0.2, 0.4, 0.6)}};
    scene.nodes = {Node{Sphere{{3, -2, 5}, 100}, 0}};
    GpuRenderer renderer(context());
    const Image image = renderer.render(scene).image;
    for (const glm::vec3& pixel : image.pixels) {
        EXPECT_EQ(pixel, glm::vec3(0.2f, 0.4f, 0.6f));
    }
}

TEST_F(GpuRendererTest, LambertUnderALightAtNormalIncidence) {
    // Light 100 above the point, intensity 10000: irradiance 1. Colour 0.5 * (ambient 0.1 + 1).
    Scene scene = lookingDownAtPlane({0, 20, 0});
    scene.lights = {PointLight{{0, 100, 0}, Color(1.0), 10000}};
    GpuRenderer renderer(context());
    const glm::vec3 center = renderer.render(scene).image.at(4, 4);
    EXPECT_NEAR(center.r, 0.55f, 1e-5f);
    EXPECT_NEAR(center.g, 0.55f, 1e-5f);
}

TEST_F(GpuRendererTest, AnOccluderOnTheWayToTheLightLeavesOnlyAmbient) {
    // Light at (50, 100, 0) seen from the origin: cos = 100 / sqrt(12500), r^2 = 12500.
    Scene scene = lookingDownAtPlane({0, 20, 0});
    scene.lights = {PointLight{{50, 100, 0}, Color(1.0), 10000}};
    GpuRenderer renderer(context());
    const float lit = 0.5f * (0.1f + float(10000.0 * (100.0 / std::sqrt(12500.0)) / 12500.0));
    EXPECT_NEAR(renderer.render(scene).image.at(4, 4).r, lit, 1e-5f);

    scene.nodes.push_back(Node{Sphere{{25, 50, 0}, 3}, 0});  // on the segment, out of the camera's view
    EXPECT_NEAR(renderer.render(scene).image.at(4, 4).r, 0.05f, 1e-6f);
}

TEST_F(GpuRendererTest, BandsOfRowsGiveTheSameImageAsOneDispatch) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 100, 75, "test");
    GpuRenderer whole(context());
    // 19 rows fit, and bands are whole rows of 8-pixel tiles: 16 rows per band, 5 bands.
    GpuRenderer banded(context(), 100 * sizeof(glm::vec4) * 19);
    EXPECT_EQ(whole.render(scene).image.pixels, banded.render(scene).image.pixels);
}

TEST_F(GpuRendererTest, LinearRowsComeInBandsThatAreTheWholeRendersRows) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 100, 75, "test");
    GpuRenderer whole(context());
    // 19 rows fit, and bands are whole rows of 8-pixel tiles: 16 rows per band, 5 bands.
    GpuRenderer banded(context(), 100 * sizeof(glm::vec4) * 19);
    const GpuRenderResult expected = whole.render(scene, Precision::F32, GpuOutput::LinearClassesAndAov);
    std::vector<std::uint32_t> firstRows;
    GpuRenderResult joined;
    const GpuRenderResult result = banded.renderLinearRows(
        scene, banded.plan(scene), GpuOutput::LinearClassesAndAov,
        [&](std::uint32_t firstRow, const GpuRenderResult& band) {
            firstRows.push_back(firstRow);
            EXPECT_EQ(band.image.width, 100u);
            EXPECT_EQ(band.image.height, std::min(16u, 75u - firstRow));
            joined.image.pixels.insert(joined.image.pixels.end(), band.image.pixels.begin(), band.image.pixels.end());
            joined.classes.insert(joined.classes.end(), band.classes.begin(), band.classes.end());
            joined.depth.insert(joined.depth.end(), band.depth.begin(), band.depth.end());
            joined.normals.insert(joined.normals.end(), band.normals.begin(), band.normals.end());
        });
    EXPECT_EQ(result.precision, Precision::F32);  // auto's choice for this scene
    EXPECT_TRUE(result.image.pixels.empty());
    EXPECT_EQ(firstRows, (std::vector<std::uint32_t>{0, 16, 32, 48, 64}));
    EXPECT_EQ(joined.image.pixels, expected.image.pixels);
    EXPECT_EQ(joined.classes, expected.classes);
    EXPECT_EQ(joined.depth, expected.depth);
    EXPECT_EQ(joined.normals, expected.normals);
}

TEST_F(GpuRendererTest, ASceneTooLargeForUniformBuffersUsesTheDataDrivenShaderAndAgrees) {
    // 48 spheres in a grid over a checkered floor, and 34 lights: past the specialized path.
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 96, 72, "test");
    for (int i = 0; i < 48; ++i) {
        scene.nodes.push_back(Node{Sphere{{-60.0 + 20.0 * (i % 8), 4.0 + (i % 3), 20.0 * (i / 8)}, 4.0}, 1});
    }
    for (int i = 0; i < 34; ++i) {
        scene.lights.push_back(PointLight{{-100.0 + 6.0 * i, 150, -50}, Color(1), 300});
    }
    ASSERT_FALSE(isSmallScene(scene));
    GpuRenderer renderer(context());
    for (Precision precision : {Precision::F32, Precision::F64}) {
        const RenderComparison c = test::compareWithReference(scene, renderer.render(scene, precision));
        EXPECT_EQ(c.topology.mismatches, 0u) << precisionName(precision);
        EXPECT_LT(c.topology.ambiguousShare(), 0.2) << precisionName(precision);
        EXPECT_LE(c.encoded.maxAbs, 1.0) << precisionName(precision);
    }
}

TEST_F(GpuRendererTest, EncodingOnTheDeviceMatchesTheHostsEncoding) {
    // The device's pow may round differently from the host's: a level at most, and rarely.
    for (const char* name : {"spheres-and-lights", "course-2024-lecture4"}) {  // sRGB, linear output
        const Scene scene = loadSceneFile(test::sourcePath(std::string("scenes/") + name + ".json"));
        GpuRenderer renderer(context());
        const GpuRenderResult linear = renderer.render(scene, Precision::F32, GpuOutput::LinearAndClasses);
        const GpuRenderResult encoded = renderer.render(scene, Precision::F32, GpuOutput::Encoded8);
        EXPECT_TRUE(encoded.classes.empty());
        ASSERT_EQ(encoded.encoded.width, scene.image.width);
        const ErrorMetrics m = compareEncoded(encodeImage(linear.image, scene.image.encoding), encoded.encoded);
        EXPECT_LE(m.maxAbs, 1.0) << name;
        EXPECT_LT(m.meanAbs, 1e-3) << name;
    }
}

TEST_F(GpuRendererTest, AntiAliasingBlendsASilhouetteOnlyWhereItCrossesAPixel) {
    // A constant white disc on black: one sample per pixel gives only black and white; 16 give
    // edge pixels in between, and the whole image keeps its total of white to within a pixel.
    Scene scene = smallScene(32, 32);
    scene.camera.fovDegrees = 60;
    scene.shaderNames = {"white"};
    scene.shaders = {ConstantShader{Color(1.0)}};
    scene.nodes = {Node{Sphere{{0, 0, 10}, 2.5}, 0}};
    GpuRenderer renderer(context());
    const auto partialPixels = [](const Image& image) {
        return std::count_if(image.pixels.begin(), image.pixels.end(),
                             [](const glm::vec3& p) { return p.r > 0.0f && p.r < 1.0f; });
    };
    const auto total = [](const Image& image) {
        double sum = 0;
        for (const glm::vec3& p : image.pixels)
            sum += p.r;
        return sum;
    };
    const Image sharp = renderer.render(scene).image;
    scene.image.samplesPerPixel = 16;
    const Image smooth = renderer.render(scene).image;
    EXPECT_EQ(partialPixels(sharp), 0);
    EXPECT_GT(partialPixels(smooth), 40);
    EXPECT_NEAR(total(smooth), total(sharp), 8.0);
    for (const glm::vec3& p : smooth.pixels) {
        EXPECT_FLOAT_EQ(p.r * 16.0f, std::round(p.r * 16.0f));  // an average of 16 samples of 0 or 1
    }
}

TEST_F(GpuRendererTest, AntiAliasedRendersAgreeWithTheCpuReference) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/spheres-and-lights.json"));
    overrideImageSize(scene, 240, 135, "test");
    overrideSamplesPerPixel(scene, 4, "test");
    GpuRenderer renderer(context());
    const RenderComparison c = test::compareWithReference(scene, renderer.render(scene, Precision::F32));
    const Tolerance tolerance;
    EXPECT_EQ(c.topology.mismatches, 0u);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, tolerance.maxRmseLevels);
}

TEST_F(GpuRendererTest, ReportsRenderTimeAfterTheWarmUp) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    GpuRenderer renderer(context());
    const GpuTiming timing = renderer.render(scene).timing;
    EXPECT_GT(timing.renderMilliseconds, 0.0);
    EXPECT_GT(timing.firstDispatchMilliseconds, 0.0);
    if (onLavapipe()) {
        EXPECT_TRUE(timing.fromTimestamps);
    }
}

}  // namespace
}  // namespace hexray
