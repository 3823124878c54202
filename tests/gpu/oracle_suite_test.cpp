// Both renderers against the exact oracle (tests/oracle/) on the generated hard rays: each ray is
// a one-pixel scene, traced by the shader (GpuRenderer::tracePixel, in f32, f64 and f32-certified,
// whose decisions are judged as f64's; auto takes the one it picks; and the data-driven kernel in f32
// and f64) and explained by the CPU reference (explainPixel), and each answer is checked
// against the oracle's for the direction that renderer really followed, at its own precision's
// unit roundoff (ray_check.h states the criteria and bounds). Prints the table that
// docs/accuracy.md shows, and records it as test properties (tools/accuracy-report.sh reads them).

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/cpu_explain.h"
#include "gpu/gpu_renderer.h"
#include "oracle/hard_rays.h"
#include "oracle/oracle.h"
#include "oracle/ray_check.h"
#include "validated_vulkan.h"
#include "unit_roundoff.h"

namespace hexray {
namespace {

using oracle::LightStatus;
using oracle::RendererRay;
using oracle::Tally;

constexpr double kFloat32Roundoff = FLOAT32_UNIT_ROUNDOFF;
constexpr double kFloat64Roundoff = FLOAT64_UNIT_ROUNDOFF;

LightStatus gpuStatus(std::uint32_t status) {
    switch (status) {
        case gpu::TRACE_LIGHT_LIT:
            return LightStatus::Lit;
        case gpu::TRACE_LIGHT_FACING_AWAY:
            return LightStatus::FacingAway;
        case gpu::TRACE_LIGHT_SHADOWED:
            return LightStatus::Shadowed;
        default:
            return LightStatus::AtPoint;
    }
}

LightStatus cpuStatus(LightReach reach) {
    switch (reach) {
        case LightReach::Lit:
            return LightStatus::Lit;
        case LightReach::FacingAway:
            return LightStatus::FacingAway;
        case LightReach::Shadowed:
            return LightStatus::Shadowed;
        default:
            return LightStatus::AtPoint;
    }
}

RendererRay fromGpu(const GpuPixelTrace& g) {
    RendererRay r;
    r.origin = g.rayOrigin;
    r.direction = g.rayDirection;
    if (g.node != PixelClass::kBackground)
        r.node = g.node;
    r.t = g.t;
    r.normal = g.normal;
    r.oddChecker = (g.flags & PixelClass::kOddCheckerBit) != 0;
    for (const GpuTraceLight& light : g.lights) {
        r.lights.push_back({gpuStatus(light.status), light.cosTheta, light.distanceSquared});
    }
    return r;
}

RendererRay fromCpu(const CpuPixelExplanation& c) {
    RendererRay r;
    r.origin = c.ray.origin;
    r.direction = c.ray.direction;
    r.worldCoordinates = true;
    if (c.nearest) {
        r.node = c.nearest->nodeIndex;
        r.t = c.nearest->hit.t;
        r.normal = c.nearest->hit.facingNormal;
    }
    r.oddChecker = (c.pixelClass.flags & PixelClass::kOddCheckerBit) != 0;
    for (const LightTerm& term : c.lights) {
        r.lights.push_back({cpuStatus(term.decision.reach), term.decision.cosTheta, term.decision.distanceSquared});
    }
    return r;
}

// One ray through one renderer, judged at that renderer's precision.
Tally judgeRay(const oracle::HardRay& ray, const RendererRay& rendered, double unitRoundoff, const std::string& who) {
    const oracle::Judged judged = oracle::judge(ray.scene, rendered.origin, rendered.direction, unitRoundoff);
    Tally tally;
    oracle::checkRay(judged, rendered, ray.family + " / " + ray.name + " / " + who, tally);
    return tally;
}

// f32-certified's answer: where the kernel had a decision in doubt (or the plan could not certify
// the scene), f64's, judged as f64;
// elsewhere f32's values, judged at f32's roundoff, and its decisions, judged at f64's (a decision
// is well conditioned for it where it is for f64).
Tally judgeCertified(const oracle::HardRay& ray, const GpuPixelTrace& trace) {
    const RendererRay rendered = fromGpu(trace);
    const oracle::Judged f64 = oracle::judge(ray.scene, rendered.origin, rendered.direction, kFloat64Roundoff);
    Tally tally;
    if (trace.tracedAgainInF64 || trace.precision == Precision::F64) {  // in doubt, or not certifiable
        oracle::checkRay(f64, rendered, ray.family + " / " + ray.name + " / gpu f32-certified (f64 pass)", tally);
        return tally;
    }
    oracle::Judged judged = oracle::judge(ray.scene, rendered.origin, rendered.direction, kFloat32Roundoff);
    judged.nodeConditioning = f64.nodeConditioning;
    judged.checkerConditioning = f64.checkerConditioning;
    judged.lightConditioning = f64.lightConditioning;
    oracle::checkRay(judged, rendered, ray.family + " / " + ray.name + " / gpu f32-certified", tally);
    return tally;
}

// One row of the table as test properties "row<i>.<field>" (gtest --gtest_output=json), in the
// table's order, for tools/accuracy-report.sh.
void recordRow(int row, const std::string& family, const std::string& renderer, const Tally& t) {
    const std::string prefix = "row" + std::to_string(row) + ".";
    const auto record = [&](const char* field, const auto& value) {
        testing::Test::RecordProperty(prefix + field, (testing::Message() << value).GetString());
    };
    record("family", family);
    record("renderer", renderer);
    record("rays", t.rays);
    record("right_decisions", t.rightDecisions);
    record("decisions", t.decisions);
    record("distances", t.distances);
    record("max_distance_ulps", t.maxDistanceUlps);
    record("values", t.values);
    record("max_value_units", t.maxValueUnits);
}

const char* const kColumns[] = {"cpu reference (f64)", "gpu f32",  "gpu f64",
                                "gpu f32-certified",   "gpu auto", "gpu f32 data-driven",
                                "gpu f64 data-driven"};

// The data-driven kernel, with candidate lists where the scene has spheres, as a scene past a
// generated kernel's capacity gets: its own forms of the tests (the fast ones where its plan
// allows them for every sphere) and its lists' depth order.
GpuPixelTrace traceDataDriven(GpuRenderer& renderer, const Scene& scene, Precision precision) {
    PlanRequest request;
    request.precision = precision;
    request.acceleration = Acceleration::Always;
    request.generatedKernel = false;
    return renderer.tracePixel(scene, renderer.plan(scene, request), 0, 0, 0);
}

using OracleSuiteTest = test::ValidatedVulkanTest;

TEST_F(OracleSuiteTest, EveryWellConditionedAnswerIsRightOnBothRenderers) {
    ASSERT_TRUE(context().selected().hasFloat64);
    GpuRenderer renderer(context());
    std::vector<std::string> families;
    std::map<std::string, std::map<std::string, Tally>> table;  // family -> column -> tally
    for (const oracle::HardRay& ray : oracle::hardRays()) {
        if (table.find(ray.family) == table.end())
            families.push_back(ray.family);
        std::map<std::string, Tally>& row = table[ray.family];
        row[kColumns[0]].add(judgeRay(ray, fromCpu(explainPixel(ray.scene, 0, 0, 0)), kFloat64Roundoff, "cpu"));
        const Tally f32 = judgeRay(ray, fromGpu(renderer.tracePixel(ray.scene, Precision::F32, 0, 0, 0)),
                                   kFloat32Roundoff, "gpu f32");
        const Tally f64 = judgeRay(ray, fromGpu(renderer.tracePixel(ray.scene, Precision::F64, 0, 0, 0)),
                                   kFloat64Roundoff, "gpu f64");
        row[kColumns[1]].add(f32);
        row[kColumns[2]].add(f64);
        row[kColumns[3]].add(judgeCertified(ray, renderer.tracePixel(ray.scene, Precision::F32Certified, 0, 0, 0)));
        Tally picked = renderer.resolve(ray.scene, Precision::Auto) == Precision::F32 ? f32 : f64;
        picked.failures.clear();  // already reported in their own column
        row[kColumns[4]].add(picked);
        row[kColumns[5]].add(judgeRay(ray, fromGpu(traceDataDriven(renderer, ray.scene, Precision::F32)),
                                      kFloat32Roundoff, "gpu f32 data-driven"));
        row[kColumns[6]].add(judgeRay(ray, fromGpu(traceDataDriven(renderer, ray.scene, Precision::F64)),
                                      kFloat64Roundoff, "gpu f64 data-driven"));
    }

    std::uint64_t rays = 0;
    std::uint64_t decisions = 0;
    int row = 0;
    for (const std::string& family : families) {
        for (const char* column : kColumns) {
            const Tally& t = table[family][column];
            std::printf("oracle-row: | %s | %s | %llu | %llu/%llu | %llu | %.2f | %llu | %.2f |\n", family.c_str(),
                        column, static_cast<unsigned long long>(t.rays),
                        static_cast<unsigned long long>(t.rightDecisions), static_cast<unsigned long long>(t.decisions),
                        static_cast<unsigned long long>(t.distances), t.maxDistanceUlps,
                        static_cast<unsigned long long>(t.values), t.maxValueUnits);
            recordRow(row++, family, column, t);
            for (const std::string& failure : t.failures)
                ADD_FAILURE() << failure;
            EXPECT_EQ(t.rightDecisions, t.decisions) << family << " " << column;
            if (column == kColumns[0])
                rays += t.rays;
            decisions += t.decisions;
        }
    }
    EXPECT_GE(rays, 500u);
    // Most decisions are well conditioned: the suite cannot pass by judging nothing.
    EXPECT_GE(decisions, 4u * rays);
}

// Issue 12, finding 1: from (3, 4, 0) on the sphere of radius 5 about the origin, along
// (3.97, -3.04, 0), f32 put the far side at 0.0999829695 for 0.0999949050: 25 ulps of the scale.
TEST_F(OracleSuiteTest, RayFromASphereReachesItsFarSideWithin8Ulps) {
    Scene base;
    base.shaders = {LambertShader{}};
    base.nodes = {Node{Sphere{{0, 0, 0}, 5.0}, 0}};
    base.lights = {PointLight{{0, 20, -20}, Color(1.0), 400.0}};
    GpuRenderer renderer(context());
    for (const glm::dvec3 direction : {glm::dvec3(3.97, -3.04, 0), glm::dvec3(4, -3.5, 0)}) {
        const Scene scene = oracle::aimedScene(base, {3, 4, 0}, direction);
        for (const auto& [precision, u] :
             {std::pair{Precision::F32, kFloat32Roundoff}, std::pair{Precision::F64, kFloat64Roundoff}}) {
            const GpuPixelTrace g = renderer.tracePixel(scene, precision, 0, 0, 0);
            const oracle::RayTruth truth = oracle::trace(scene, g.rayOrigin, g.rayDirection);
            ASSERT_EQ(g.node, 0u);
            const double ulps = std::abs(g.t - truth.t) / oracle::ulpAt(truth.scale, u);
            std::printf("finding 1 %s: t %.10f, exactly %.10f: %.2f ulps\n",
                        std::string(precisionName(precision)).c_str(), g.t, truth.t, ulps);
            EXPECT_LE(ulps, oracle::kDistanceUlps) << precisionName(precision);
        }
    }
}

}  // namespace
}  // namespace hexray
