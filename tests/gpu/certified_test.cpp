// f32-certified (render_plan.h): every pixel is the f32 kernel's, or, where the kernel found a
// decision in doubt, the f64 kernel's, rendered again from a list; its decisions then pass the CPU
// reference's near-ties at f64's roundoff, which plain f32 does not; and the plan falls back to f64
// where it cannot certify.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/gpu_renderer.h"
#include "gpu/plan_refused.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class CertifiedTest : public test::ValidatedVulkanTest {
protected:
    void SetUp() override {
        test::ValidatedVulkanTest::SetUp();
        if (!context().selected().hasFloat64) {
            GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
        }
    }
};

Scene shippedScene(const std::string& name, std::uint32_t width, std::uint32_t height, std::uint32_t spp = 1) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/" + name));
    scene.image.width = width;
    scene.image.height = height;
    scene.image.samplesPerPixel = spp;
    return scene;
}

// How the certified render's pixels relate to the f32 and f64 renders'.
struct Composition {
    std::size_t fromF32 = 0;      // equal to the f32 render's pixel (and class)
    std::size_t fromF64 = 0;      // not, but equal to the f64 render's
    std::size_t fromNeither = 0;  // equal to neither
};

Composition composition(const GpuRenderResult& certified, const GpuRenderResult& f32, const GpuRenderResult& f64) {
    Composition c;
    for (std::size_t i = 0; i < certified.image.pixels.size(); ++i) {
        const auto same = [&](const GpuRenderResult& other) {
            return certified.image.pixels[i] == other.image.pixels[i] && certified.classes[i] == other.classes[i];
        };
        if (same(f32)) {
            ++c.fromF32;
        } else if (same(f64)) {
            ++c.fromF64;
        } else {
            ++c.fromNeither;
        }
    }
    return c;
}

TEST_F(CertifiedTest, EveryPixelIsTheF32RendersOrWhereInDoubtTheF64Renders) {
    GpuRenderer renderer(context());
    for (const Scene& scene :
         {shippedScene("lecture-demo.json", 320, 240), shippedScene("spheres-and-lights.json", 320, 180),
          shippedScene("spheres-and-lights.json", 160, 90, 4)}) {
        const GpuRenderResult certified = renderer.render(scene, Precision::F32Certified);
        ASSERT_EQ(certified.precision, Precision::F32Certified);
        const Composition c =
            composition(certified, renderer.render(scene, Precision::F32), renderer.render(scene, Precision::F64));
        const CertifiedFallback& pass = certified.timing.fallback;
        EXPECT_EQ(c.fromNeither, 0u);
        EXPECT_GT(pass.pixels, 0u);  // these scenes have pixels on checker edges and silhouettes
        EXPECT_LE(c.fromF64, pass.pixels);
        EXPECT_EQ(pass.totalPixels, std::uint64_t(scene.image.width) * scene.image.height);
        EXPECT_LT(pass.pixels * 10, pass.totalPixels);  // a few pixels, not the image
        EXPECT_GE(pass.vectors * 8, pass.pixels);
        EXPECT_LE(pass.vectors, pass.pixels);
    }
}

// The f64 pass runs per band of rows, its list in rows of the whole image: a render in bands
// gives the image a render in one band gives, linear and encoded.
TEST_F(CertifiedTest, BandsOfRowsGiveTheSameImage) {
    const Scene scene = shippedScene("spheres-and-lights.json", 320, 180);
    GpuRenderer whole(context());
    GpuRenderer banded(context(), 320 * sizeof(GpuPixel) * 16);  // bands of 16 rows
    const GpuRenderResult linear = whole.render(scene, Precision::F32Certified);
    const GpuRenderResult bandedLinear = banded.render(scene, Precision::F32Certified);
    EXPECT_EQ(bandedLinear.image.pixels, linear.image.pixels);
    EXPECT_EQ(bandedLinear.classes, linear.classes);
    EXPECT_EQ(bandedLinear.timing.fallback.pixels, linear.timing.fallback.pixels);
    const GpuRenderResult encoded = whole.render(scene, Precision::F32Certified, GpuOutput::Encoded8);
    const GpuRenderResult bandedEncoded = banded.render(scene, Precision::F32Certified, GpuOutput::Encoded8);
    EXPECT_EQ(bandedEncoded.encoded.bytes, encoded.encoded.bytes);
    EXPECT_EQ(encoded.timing.fallback.pixels, linear.timing.fallback.pixels);
}

// Judged at f64's roundoff, plain f32 makes decisions the reference calls clear the wrong way;
// certified f32 makes none.
TEST_F(CertifiedTest, DecidesWhatF64DecidesWhereF32DoesNot) {
    GpuRenderer renderer(context());
    const Scene scene = shippedScene("spheres-and-lights.json", 480, 270);
    const CpuRender reference =
        renderOnCpu(scene, 0, Acceleration::Auto, false, decisionRoundoff(Precision::F32Certified));
    const auto mismatches = [&](Precision precision) {
        const GpuRenderResult gpu = renderer.render(scene, precision);
        return compareRenders(reference.image, reference.classes, reference.ambiguity, gpu.image, gpu.classes,
                              scene.image.encoding)
            .topology.mismatches;
    };
    EXPECT_GT(mismatches(Precision::F32), 0u);
    EXPECT_EQ(mismatches(Precision::F32Certified), 0u);
    EXPECT_EQ(mismatches(Precision::F64), 0u);
}

TEST_F(CertifiedTest, ThePlanKeepsAnF64PlanForTheListedPixels) {
    GpuRenderer renderer(context());
    const RenderPlan plan = renderer.plan(shippedScene("lecture-demo.json", 64, 48), {Precision::F32Certified});
    EXPECT_EQ(plan.precision, Precision::F32Certified);
    EXPECT_EQ(plan.width, FloatWidth::F32);
    ASSERT_TRUE(plan.kernel.code);
    EXPECT_TRUE(plan.kernel.code->certified);
    ASSERT_TRUE(plan.fallback);
    EXPECT_EQ(plan.fallback->precision, Precision::F64);
    ASSERT_TRUE(plan.fallback->kernel.code);
    EXPECT_TRUE(plan.fallback->kernel.code->pixelList);
    EXPECT_FALSE(plan.fallback->kernel.code->certified);
    EXPECT_FALSE(plan.fallback->fallback);
    EXPECT_TRUE(plan.warnings.empty());
}

TEST_F(CertifiedTest, WhatItCannotCertifyRendersInF64WithAWarning) {
    GpuRenderer renderer(context());
    const Scene inside = loadSceneFile(test::sourcePath("scenes/hard/camera-inside-sphere.json"));
    const RenderPlan eyeInside = renderer.plan(inside, {Precision::F32Certified});
    EXPECT_EQ(eyeInside.precision, Precision::F64);
    EXPECT_FALSE(eyeInside.fallback);
    ASSERT_EQ(eyeInside.warnings.size(), 1u);
    EXPECT_NE(eyeInside.warnings[0].find("the eye is inside a sphere"), std::string::npos) << eyeInside.warnings[0];

    const Scene demo = shippedScene("lecture-demo.json", 64, 48);
    const RenderPlan dataDriven = renderer.plan(demo, {.precision = Precision::F32Certified, .generatedKernel = false});
    EXPECT_EQ(dataDriven.precision, Precision::F64);
    ASSERT_EQ(dataDriven.warnings.size(), 1u);
    EXPECT_NE(dataDriven.warnings[0].find("generated kernels only"), std::string::npos) << dataDriven.warnings[0];
}

TEST(CertifiedPlanTest, ADeviceWithoutFloat64RefusesIt) {
    const Scene demo = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    const DeviceAbilities noFloat64{.name = "a device", .float64 = false};
    try {
        planRender(demo, {Precision::F32Certified}, noFloat64);
        FAIL() << "planned without float64";
    } catch (const PlanRefused& refused) {
        EXPECT_EQ(refused.refusal(), Refusal::NoFloat64);
        EXPECT_NE(std::string(refused.what()).find("--precision f32-certified needs shaderFloat64"), std::string::npos)
            << refused.what();
    }
}

}  // namespace
}  // namespace hexray
