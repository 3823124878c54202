// `hexray pixel`'s two sources: the shader's trace mode and the CPU reference's explainPixel,
// on pixels of the lecture's demo scene whose hit and light terms are known by hand
// (support/lecture_demo.h), and the shader's AOV mode against the same closed forms.

#include <cmath>

#include <gtest/gtest.h>

#include "cpu/cpu_explain.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "support/lecture_demo.h"
#include "support/test_paths.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

namespace demo = test::lecture_demo;
using PixelTraceTest = test::ValidatedVulkanTest;

Scene demoScene() {
    return loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
}

// Both backends explain the same pixel the same way, within float32 rounding.
void expectAgreement(const GpuPixelTrace& g, const CpuPixelExplanation& c) {
    EXPECT_EQ(g.node, c.pixelClass.node);
    EXPECT_EQ(g.flags, c.pixelClass.flags);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(g.rayOrigin[i], c.ray.origin[i], 1e-4);
        EXPECT_NEAR(g.rayDirection[i], c.ray.direction[i], 1e-6);
        EXPECT_NEAR(g.pixelColor[i], c.pixelColor[i], 1e-5);
    }
    ASSERT_EQ(g.candidates.size(), c.candidates.size());
    for (std::size_t i = 0; i < c.candidates.size(); ++i) {
        if (c.candidates[i]) {
            EXPECT_NEAR(g.candidates[i], c.candidates[i]->t, 1e-5 * c.candidates[i]->t) << "node " << i;
        } else {
            EXPECT_TRUE(std::isinf(g.candidates[i])) << "node " << i;
        }
    }
}

TEST_F(PixelTraceTest, LitFloorPixelMatchesTheClosedFormOnBothBackends) {
    const Scene scene = demoScene();
    GpuRenderer renderer(context());
    for (const Precision precision : {Precision::F32, Precision::F64}) {
        SCOPED_TRACE(std::string(precisionName(precision)));
        const GpuPixelTrace g = renderer.tracePixel(scene, precision, demo::kFloorX, demo::kFloorY, 0);
        const CpuPixelExplanation c = explainPixel(scene, demo::kFloorX, demo::kFloorY, 0);

        const glm::dvec3 d = demo::direction(demo::kFloorX, demo::kFloorY, 800, 600);
        const double t = *demo::planeT(d);
        const glm::dvec3 p = demo::kEye + t * d;
        ASSERT_FALSE(demo::sphereT(d));
        ASSERT_GT(demo::segmentClearance(p), demo::kSphereRadius);  // so the light is visible
        const glm::dvec3 toLight = demo::kLight - p;
        const double r2 = glm::dot(toLight, toLight);
        const double cosTheta = toLight.y / std::sqrt(r2);

        EXPECT_EQ(g.node, 0u);
        EXPECT_NEAR(g.t, t, 1e-5 * t);
        EXPECT_NEAR(c.nearest->hit.t, t, 1e-12 * t);
        EXPECT_NEAR(g.position.x, p.x, 1e-4);
        EXPECT_EQ(g.position.y, 0.0);  // snapped onto the plane
        EXPECT_NEAR(g.position.z, p.z, 1e-4);
        EXPECT_EQ(g.normal, glm::dvec3(0, 1, 0));
        // Cell (floor(x / 20), floor(z / 20)) = (0, 1): odd, color2 = (0.2, 0.3, 0.6).
        EXPECT_EQ(*c.checkerCell, glm::dvec2(0, 1));
        EXPECT_EQ(g.flags & PixelClass::kOddCheckerBit, PixelClass::kOddCheckerBit);
        EXPECT_NEAR(g.albedo.g, 0.3f, 1e-7);
        ASSERT_EQ(g.lights.size(), 1u);
        EXPECT_EQ(g.lights[0].status, gpu::TRACE_LIGHT_LIT);
        EXPECT_EQ(c.lights[0].decision.reach, LightReach::Lit);
        EXPECT_NEAR(g.lights[0].cosTheta, cosTheta, 1e-6);
        EXPECT_NEAR(g.lights[0].distanceSquared, r2, 1e-5 * r2);
        EXPECT_NEAR(c.lights[0].decision.cosTheta, cosTheta, 1e-12);
        EXPECT_NEAR(g.lights[0].contribution.r, 10000.0 * cosTheta / r2, 1e-5);
        EXPECT_NEAR(g.pixelColor.b, 0.6 * (0.15 + 10000.0 * cosTheta / r2), 1e-5);
        expectAgreement(g, c);
    }
}

TEST_F(PixelTraceTest, ShadowCentreIsShadowedOnBothBackends) {
    const Scene scene = demoScene();
    GpuRenderer renderer(context());
    const GpuPixelTrace g = renderer.tracePixel(scene, Precision::F32, demo::kShadowX, demo::kShadowY, 0);
    const CpuPixelExplanation c = explainPixel(scene, demo::kShadowX, demo::kShadowY, 0);
    const glm::dvec3 d = demo::direction(demo::kShadowX, demo::kShadowY, 800, 600);
    const glm::dvec3 p = demo::kEye + *demo::planeT(d) * d;
    ASSERT_LT(demo::segmentClearance(p), 0.5 * demo::kSphereRadius);  // well inside the shadow
    EXPECT_EQ(g.node, 0u);
    EXPECT_EQ(g.lights[0].status, gpu::TRACE_LIGHT_SHADOWED);
    EXPECT_EQ(c.lights[0].decision.reach, LightReach::Shadowed);
    EXPECT_GT(g.lights[0].cosTheta, 0.0);
    EXPECT_EQ(g.lights[0].contribution, glm::vec3(0));
    expectAgreement(g, c);
}

// A light below the floor: the floor faces away from it, so it contributes nothing and its
// shadow ray is not asked about (length 0), in both precisions.
TEST_F(PixelTraceTest, LightBelowTheFloorFacesAwayOnBothBackends) {
    Scene scene = demoScene();
    scene.lights[0].position.y = -10.0;
    GpuRenderer renderer(context());
    for (const Precision precision : {Precision::F32, Precision::F64}) {
        SCOPED_TRACE(std::string(precisionName(precision)));
        const GpuPixelTrace g = renderer.tracePixel(scene, precision, demo::kFloorX, demo::kFloorY, 0);
        const CpuPixelExplanation c = explainPixel(scene, demo::kFloorX, demo::kFloorY, 0);
        EXPECT_EQ(g.node, 0u);
        ASSERT_EQ(g.lights.size(), 1u);
        EXPECT_EQ(g.lights[0].status, gpu::TRACE_LIGHT_FACING_AWAY);
        EXPECT_EQ(c.lights[0].decision.reach, LightReach::FacingAway);
        EXPECT_LT(g.lights[0].cosTheta, 0.0);
        EXPECT_EQ(g.lights[0].shadowLength, 0.0);
        EXPECT_EQ(g.lights[0].contribution, glm::vec3(0));
        EXPECT_EQ(g.flags & PixelClass::litBit(0), 0u);
        EXPECT_NEAR(g.pixelColor.b, 0.6 * 0.15, 1e-6);  // ambient only, odd cell
        expectAgreement(g, c);
    }
}

TEST_F(PixelTraceTest, SpherePixelShowsBothCandidatesAndTheNearerWins) {
    const Scene scene = demoScene();
    GpuRenderer renderer(context());
    const GpuPixelTrace g = renderer.tracePixel(scene, Precision::F32, demo::kSphereX, demo::kSphereY, 0);
    const CpuPixelExplanation c = explainPixel(scene, demo::kSphereX, demo::kSphereY, 0);
    const glm::dvec3 d = demo::direction(demo::kSphereX, demo::kSphereY, 800, 600);
    const double t = *demo::sphereT(d);
    EXPECT_EQ(g.node, 1u);
    EXPECT_NEAR(g.t, t, 1e-5 * t);
    EXPECT_NEAR(g.candidates[1], t, 1e-5 * t);
    // The ray rises slightly (d.y = +0.001 / |d|): the floor is a miss.
    ASSERT_FALSE(demo::planeT(d));
    EXPECT_TRUE(std::isinf(g.candidates[0]));
    const glm::dvec3 outward = glm::normalize(demo::kEye + t * d - demo::kSphereCenter);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(g.normal[i], outward[i], 1e-5);
    }
    EXPECT_EQ(g.lights[0].status, gpu::TRACE_LIGHT_LIT);
    expectAgreement(g, c);
}

TEST_F(PixelTraceTest, BackgroundPixelHasNoHitAndNoLightTerms) {
    const Scene scene = demoScene();
    GpuRenderer renderer(context());
    const GpuPixelTrace g = renderer.tracePixel(scene, Precision::F32, 0, 0, 0);
    EXPECT_EQ(g.node, PixelClass::kBackground);
    EXPECT_TRUE(std::isinf(g.candidates[0]) && std::isinf(g.candidates[1]));
    EXPECT_EQ(g.lights[0].status, gpu::TRACE_LIGHT_NOT_EVALUATED);
    EXPECT_EQ(g.pixelColor, glm::vec3(0));
    expectAgreement(g, explainPixel(scene, 0, 0, 0));
}

TEST_F(PixelTraceTest, TracedSampleIsTheOneAsked) {
    Scene scene = demoScene();
    scene.image.samplesPerPixel = 4;
    GpuRenderer renderer(context());
    const GpuPixelTrace first = renderer.tracePixel(scene, Precision::F32, demo::kFloorX, demo::kFloorY, 0);
    const GpuPixelTrace third = renderer.tracePixel(scene, Precision::F32, demo::kFloorX, demo::kFloorY, 2);
    EXPECT_NE(first.rayDirection, third.rayDirection);
    EXPECT_EQ(first.pixelColor, third.pixelColor);  // the pixel's average does not depend on it
    expectAgreement(third, explainPixel(scene, demo::kFloorX, demo::kFloorY, 2));
    // The pixel's colour is what render() produces.
    const GpuRenderResult rendered = renderer.render(scene, Precision::F32);
    EXPECT_NEAR(glm::length(rendered.image.at(demo::kFloorX, demo::kFloorY) - first.pixelColor), 0.0f, 1e-6f);
}

TEST_F(PixelTraceTest, AovModeGivesDepthAndNormalsAndTheSameImage) {
    const Scene scene = demoScene();
    GpuRenderer renderer(context());
    const GpuRenderResult plain = renderer.render(scene, Precision::F32);
    const GpuRenderResult aov = renderer.render(scene, Precision::F32, GpuOutput::LinearClassesAndAov);
    for (std::size_t i = 0; i < plain.image.pixels.size(); ++i) {
        ASSERT_NEAR(glm::length(plain.image.pixels[i] - aov.image.pixels[i]), 0.0f, 1e-6f) << "pixel " << i;
    }
    EXPECT_EQ(plain.classes, aov.classes);
    const std::size_t floor = std::size_t(demo::kFloorY) * 800 + demo::kFloorX;
    const double t = *demo::planeT(demo::direction(demo::kFloorX, demo::kFloorY, 800, 600));
    EXPECT_NEAR(aov.depth[floor], t, 1e-5 * t);
    EXPECT_EQ(aov.normals[floor], glm::vec3(0, 1, 0));
    EXPECT_TRUE(std::isinf(aov.depth[0]));
    EXPECT_EQ(aov.normals[0], glm::vec3(0));

    // Against the CPU reference's AOVs wherever both show the same node, in f64: in f32 the
    // floor's rows near the horizon amplify the direction's rounding (1e-7 / |d.y|) in t.
    const GpuRenderResult aov64 = renderer.render(scene, Precision::F64, GpuOutput::LinearClassesAndAov);
    const CpuRender cpu = renderOnCpu(scene, 0, Acceleration::Auto, true);
    const CpuRender reference = renderOnCpu(scene);
    std::size_t compared = 0;
    for (std::size_t i = 0; i < cpu.depth.size(); ++i) {
        if (reference.classes[i].node != aov64.classes[i].node) {
            continue;
        }
        ++compared;
        if (reference.classes[i].node == PixelClass::kBackground) {
            ASSERT_TRUE(std::isinf(aov64.depth[i]) && std::isinf(cpu.depth[i])) << "pixel " << i;
            continue;
        }
        ASSERT_NEAR(aov64.depth[i], cpu.depth[i], 1e-6 * cpu.depth[i]) << "pixel " << i;
        ASSERT_NEAR(glm::length(aov64.normals[i] - cpu.normals[i]), 0.0f, 1e-6f) << "pixel " << i;
    }
    EXPECT_GT(compared, 479000u);  // of 480000
}

// A scene large enough for the candidate lists: the trace and AOV modes follow the lists there
// too, and agree with the CPU reference.
TEST_F(PixelTraceTest, TraceAndAovModesFollowTheCandidateListsInAManySphereScene) {
    Scene scene = makeRandomSpheresScene(500, 1);
    overrideImageSize(scene, 96, 54, "test");
    GpuRenderer renderer(context());
    const GpuRenderResult aov = renderer.render(scene, Precision::F64, GpuOutput::LinearClassesAndAov);
    ASSERT_TRUE(aov.usedCandidateLists);
    const CpuRender reference = renderOnCpu(scene);
    const CpuRender cpu = renderOnCpu(scene, 0, Acceleration::Auto, true);
    std::size_t traced = 0;
    std::size_t spheres = 0;
    for (std::uint32_t y = 0; y < 54; y += 7) {
        for (std::uint32_t x = 0; x < 96; x += 11) {
            const std::size_t i = std::size_t(y) * 96 + x;
            if (reference.margins[i] < kAmbiguityMargin) {
                continue;  // either answer would be honest
            }
            const GpuPixelTrace g = renderer.tracePixel(scene, Precision::F64, x, y, 0);
            ASSERT_TRUE(g.usedCandidateLists);
            expectAgreement(g, explainPixel(scene, x, y, 0));
            EXPECT_EQ(aov.classes[i], reference.classes[i]) << "pixel " << x << ", " << y;
            if (!std::isinf(cpu.depth[i])) {
                EXPECT_NEAR(aov.depth[i], cpu.depth[i], 1e-5 * cpu.depth[i]) << "pixel " << x << ", " << y;
            }
            ++traced;
            spheres += g.node != PixelClass::kBackground && g.node != 0 ? 1 : 0;
        }
    }
    EXPECT_GE(traced, 50u);
    EXPECT_GE(spheres, 5u);  // not only floor and sky
}

}  // namespace
}  // namespace hexray
