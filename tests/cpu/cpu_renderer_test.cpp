// The CPU reference end to end: tiny scenes whose pixels can be worked out by hand.

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"

using namespace hexray;

namespace {

void expectPixel(const Image& image, std::uint32_t x, std::uint32_t y, const Color& expected, double tolerance = 1e-6) {
    // The image holds float: compare with the expected value rounded the same way.
    const glm::vec3& actual = image.at(x, y);
    const glm::vec3 expectedFloat(expected);
    EXPECT_NEAR(actual.x, expectedFloat.x, tolerance) << "pixel (" << x << ", " << y << ")";
    EXPECT_NEAR(actual.y, expectedFloat.y, tolerance) << "pixel (" << x << ", " << y << ")";
    EXPECT_NEAR(actual.z, expectedFloat.z, tolerance) << "pixel (" << x << ", " << y << ")";
}

// 8x6, FOV 90, aspect 4/3, corner sampling: the sheet is TL (-0.8, 0.6, 1), right (1.6, 0, 0),
// down (0, -1.2, 0), so pixel (x, y) aims at (-0.8 + 0.2x, 0.6 - 0.2y, 1).
// Camera at (0, 2, 0) above a Lambert plane y = 0.
Scene groundScene() {
    Scene scene;
    scene.image.width = 8;
    scene.image.height = 6;
    scene.image.sampling = Sampling::Corner;
    scene.camera.position = {0, 2, 0};
    scene.background = {0.1, 0.2, 0.3};
    scene.ambient = Color(0.1);
    scene.lights.push_back(PointLight{{-1, 12, 9}, Color(1.0), 169.0});
    scene.shaders.push_back(LambertShader{{0.5, 1.0, 0.25}});
    scene.nodes.push_back(Node{Plane{0.0}, 0});
    return scene;
}

// 37x23, two checkered nodes, a Lambert sphere and two lights: no two rows alike.
Scene variedScene() {
    Scene scene;
    scene.image.width = 37;
    scene.image.height = 23;
    scene.camera.position = {3, 40, -90};
    scene.camera.yawDegrees = 10;
    scene.camera.pitchDegrees = -20;
    scene.camera.rollDegrees = 5;
    scene.background = {0.05, 0.1, 0.2};
    scene.ambient = Color(0.15);
    scene.lights.push_back(PointLight{{30, 100, -70}, Color(1.0), 10000.0});
    scene.lights.push_back(PointLight{{-50, 30, 0}, {0.5, 0.2, 0.1}, 3000.0});
    scene.shaders.push_back(CheckerShader{{0, 0, 0.8}, {0.2, 0.3, 0.6}, 20.0});
    scene.shaders.push_back(CheckerShader{{0.8, 0, 0}, {0.6, 0.4, 0.1}, 9.0});
    scene.shaders.push_back(LambertShader{{0.7, 0.7, 0.7}});
    scene.nodes.push_back(Node{Plane{15.0}, 0});
    scene.nodes.push_back(Node{Sphere{{-10, 60, 0}, 30}, 1});
    scene.nodes.push_back(Node{Sphere{{40, 25, 10}, 10}, 2});
    return scene;
}

}  // namespace

TEST(RenderOnCpu, ImageHasTheScenesSize) {
    const Image image = renderOnCpu(groundScene(), 1).image;
    EXPECT_EQ(image.width, 8u);
    EXPECT_EQ(image.height, 6u);
    EXPECT_EQ(image.pixels.size(), 48u);
}

TEST(RenderOnCpu, PixelLookingAtTheSkyGetsTheBackground) {
    const Image image = renderOnCpu(groundScene(), 1).image;
    expectPixel(image, 0, 0, {0.1, 0.2, 0.3}, 0.0);  // aims up at (-0.8, 0.6, 1)
    expectPixel(image, 7, 2, {0.1, 0.2, 0.3}, 0.0);  // aims up at (0.6, 0.2, 1)
    // Pixel (4, 3) aims at the sheet's centre, (0, 0, 1): parallel to the plane, a miss.
    expectPixel(image, 4, 3, {0.1, 0.2, 0.3}, 0.0);
}

TEST(RenderOnCpu, LambertOnThePlaneMatchesHandComputation) {
    const Image image = renderOnCpu(groundScene(), 1).image;
    // Pixel (0, 5) aims at (-0.8, -0.4, 1); from height 2 it meets y = 0 at (-4, 0, 5).
    // To the light (-1, 12, 9): (3, 12, 4), r = 13, cos = 12/13; 169 * (12/13) / 169 = 12/13.
    const Color albedo(0.5, 1.0, 0.25);
    expectPixel(image, 0, 5, albedo * (0.1 + 12.0 / 13.0));
    // Pixel (1, 5) aims at (-0.6, -0.4, 1) and meets the plane at (-3, 0, 5).
    // To the light: (2, 12, 4), r^2 = 164, cos = 12 / sqrt(164).
    expectPixel(image, 1, 5, albedo * (0.1 + 169.0 * (12.0 / std::sqrt(164.0)) / 164.0));
}

TEST(RenderOnCpu, ShadowedPixelGetsOnlyAmbient) {
    // A ball of radius 1 at (-2.5, 6, 7), on the segment from (-4, 0, 5) to the light (-1, 12, 9)
    // (its midpoint), puts pixel (0, 5) in shadow.
    Scene scene = groundScene();
    scene.nodes.push_back(Node{Sphere{{-2.5, 6, 7}, 1.0}, 0});
    const Image image = renderOnCpu(scene, 1).image;
    expectPixel(image, 0, 5, Color(0.5, 1.0, 0.25) * 0.1);
}

TEST(RenderOnCpu, CentreSamplingAimsAtPixelCentres) {
    // 2x2, FOV 90, aspect 1: m = 1/sqrt(2); the centre of pixel (0, 1) is at sheet fraction
    // (1/4, 3/4), aiming at (-m/2, -m/2, 1). From the origin it meets y = -1 at (-1, -1, 2 sqrt 2).
    // A light 10 straight above that point with intensity 100 gives exactly 1.
    Scene scene;
    scene.image.width = 2;
    scene.image.height = 2;
    scene.image.sampling = Sampling::Center;
    scene.background = {0, 0, 1};
    scene.lights.push_back(PointLight{{-1, 9, 2 * std::sqrt(2.0)}, Color(1.0), 100.0});
    scene.shaders.push_back(LambertShader{{0.3, 0.6, 0.9}});
    scene.nodes.push_back(Node{Plane{-1.0}, 0});
    const Image image = renderOnCpu(scene, 1).image;
    expectPixel(image, 0, 1, {0.3, 0.6, 0.9});
    expectPixel(image, 0, 0, {0, 0, 1}, 0.0);  // aims up
    // Corner sampling would aim pixel (0, 1) at (-m, 0, 1), parallel to the plane.
    scene.image.sampling = Sampling::Corner;
    expectPixel(renderOnCpu(scene, 1).image, 0, 1, {0, 0, 1}, 0.0);
}

TEST(RenderOnCpu, ConstantSphereFillingTheViewIsItsColourEverywhere) {
    // A sphere of radius 9.9 at distance 10 spans asin(0.99) = 82 degrees each way from the
    // centre, more than the 45-degree half-diagonal of a FOV-90 frame. Constant colours are
    // not lit and not clamped.
    Scene scene;
    scene.image.width = 8;
    scene.image.height = 6;
    scene.background = {0, 1, 0};
    scene.ambient = Color(0.5);
    scene.lights.push_back(PointLight{{0, 0, -1}, Color(1.0), 1000.0});
    scene.shaders.push_back(ConstantShader{{2.0, -0.5, 10.0}});
    scene.nodes.push_back(Node{Sphere{{0, 0, 10}, 9.9}, 0});
    const Image image = renderOnCpu(scene, 1).image;
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            expectPixel(image, x, y, {2.0, -0.5, 10.0}, 0.0);
        }
    }
}

TEST(RenderOnCpu, ThreadCountsGiveIdenticalImages) {
    const Scene scene = variedScene();
    const CpuRender single = renderOnCpu(scene, 1);
    std::set<std::tuple<float, float, float>> distinct;
    for (const glm::vec3& p : single.image.pixels) {
        distinct.insert({p.x, p.y, p.z});
    }
    ASSERT_GT(distinct.size(), 10u) << "the scene should not be trivially uniform";

    for (unsigned threads : {3u, 0u, 100u}) {
        const CpuRender render = renderOnCpu(scene, threads);
        ASSERT_EQ(render.image.width, single.image.width);
        ASSERT_EQ(render.image.height, single.image.height);
        EXPECT_TRUE(render.image.pixels == single.image.pixels) << threads << " threads";
        EXPECT_TRUE(render.classes == single.classes) << threads << " threads";
        EXPECT_TRUE(render.margins == single.margins) << threads << " threads";
    }
}

TEST(CpuBandRenderer, BandsOfAnyHeightAreTheWholeRendersRows) {
    const Scene scene = variedScene();
    const CpuRender whole = renderOnCpu(scene, 2, Acceleration::Auto, true);
    const CpuBandRenderer renderer(scene, 2, Acceleration::Auto, true);
    const std::size_t width = scene.image.width;
    for (const std::uint32_t bandRows : {1u, 5u, 23u}) {
        CpuRender band;  // reused, as the commands do
        for (std::uint32_t first = 0; first < scene.image.height; first += bandRows) {
            const std::uint32_t rows = std::min(bandRows, scene.image.height - first);
            renderer.render(first, rows, band);
            ASSERT_EQ(band.image.height, rows);
            const auto part = [&](const auto& values) {
                const auto begin = values.begin() + std::ptrdiff_t(first * width);
                return std::vector(begin, begin + std::ptrdiff_t(rows * width));
            };
            EXPECT_TRUE(band.image.pixels == part(whole.image.pixels)) << bandRows << " rows, from " << first;
            EXPECT_TRUE(band.classes == part(whole.classes)) << bandRows << " rows, from " << first;
            EXPECT_TRUE(band.margins == part(whole.margins)) << bandRows << " rows, from " << first;
            EXPECT_TRUE(band.depth == part(whole.depth)) << bandRows << " rows, from " << first;
            EXPECT_TRUE(band.normals == part(whole.normals)) << bandRows << " rows, from " << first;
        }
    }
}

// The rows-done reports (compare's progress line) count up to the band's rows, and the band is
// the one rendered without them.
TEST(CpuBandRenderer, ReportsRowsDoneUpToTheBandWithTheSameRows) {
    const Scene scene = variedScene();
    const CpuBandRenderer renderer(scene, 2, Acceleration::Auto, true);
    CpuRender quiet;
    renderer.render(3, 17, quiet);
    std::vector<std::uint32_t> reports;
    CpuRender reported;
    renderer.render(3, 17, reported, [&](std::uint32_t rows) { reports.push_back(rows); });
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.back(), 17u);
    EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
    EXPECT_TRUE(reported.image.pixels == quiet.image.pixels);
    EXPECT_TRUE(reported.classes == quiet.classes);
    EXPECT_TRUE(reported.margins == quiet.margins);
}

TEST(CpuBandRenderer, ThreadsAreCappedAtTheImageHeightAndTheMaximum) {
    Scene scene = variedScene();
    EXPECT_EQ(CpuBandRenderer(scene, 4000000000u).threadCount(), 23u);
    EXPECT_EQ(CpuBandRenderer(scene, 3).threadCount(), 3u);
    scene.image.height = 5000;
    EXPECT_EQ(CpuBandRenderer(scene, 4000000000u).threadCount(), kMaxCpuThreads);
}

TEST(CpuBandRenderer, RowsPerBandGrowWithTheBytesAndShrinkWithTheWidth) {
    const Scene scene = variedScene();
    const std::size_t pixelBytes = sizeof(glm::vec3) + sizeof(PixelClass) + sizeof(float) + sizeof(PixelAmbiguity);
    const CpuBandRenderer renderer(scene, 1);
    EXPECT_EQ(renderer.rowsPerBand(37 * pixelBytes * 5), 5u);
    EXPECT_EQ(renderer.rowsPerBand(1), 1u);                      // at least one row
    EXPECT_EQ(renderer.rowsPerBand(std::size_t(1) << 40), 23u);  // at most the image
    // AOVs take room too: fewer rows in the same bytes.
    EXPECT_LT(CpuBandRenderer(scene, 1, Acceleration::Auto, true).rowsPerBand(37 * pixelBytes * 5), 5u);
}

TEST(RenderOnCpu, EmptyImage) {
    Scene scene = groundScene();
    scene.image.width = 0;
    scene.image.height = 0;
    const CpuRender render = renderOnCpu(scene, 3);
    EXPECT_EQ(render.image.pixels.size(), 0u);
    EXPECT_EQ(render.classes.size(), 0u);
    EXPECT_EQ(render.margins.size(), 0u);
}

TEST(RenderOnCpu, BadShaderIndexThrowsInsteadOfCrashing) {
    Scene scene = groundScene();
    scene.nodes.push_back(Node{Plane{-5.0}, 7});
    EXPECT_THROW(renderOnCpu(scene, 2), std::out_of_range);
}

// ---------------------------------------------------------------- classification and margins

TEST(RenderOnCpu, ClassesAndMarginsHaveOneEntryPerPixel) {
    const CpuRender render = renderOnCpu(groundScene(), 1);
    EXPECT_EQ(render.classes.size(), 48u);
    EXPECT_EQ(render.margins.size(), 48u);
}

TEST(RenderOnCpu, BackgroundPixelsAreClassifiedAsBackground) {
    const CpuRender render = renderOnCpu(groundScene(), 1);
    EXPECT_EQ(render.classes[0 * 8 + 0], (PixelClass{PixelClass::kBackground, 0}));
    EXPECT_EQ(render.classes[2 * 8 + 7], (PixelClass{PixelClass::kBackground, 0}));
    EXPECT_EQ(render.classes[3 * 8 + 4], (PixelClass{PixelClass::kBackground, 0}));
}

TEST(RenderOnCpu, LitPlanePixelNamesItsNodeAndLight) {
    const CpuRender render = renderOnCpu(groundScene(), 1);
    EXPECT_EQ(render.classes[5 * 8 + 0], (PixelClass{0, PixelClass::litBit(0)}));
    EXPECT_EQ(render.classes[5 * 8 + 1], (PixelClass{0, PixelClass::litBit(0)}));
}

TEST(RenderOnCpu, ShadowedPixelHasNoLitBit) {
    Scene scene = groundScene();
    scene.nodes.push_back(Node{Sphere{{-2.5, 6, 7}, 1.0}, 0});
    const CpuRender render = renderOnCpu(scene, 1);
    EXPECT_EQ(render.classes[5 * 8 + 0], (PixelClass{0, 0}));
    // Pixel (7, 5) aims at (0.6, -0.4, 1) and lands at (3, 0, 5), well clear of the ball's shadow.
    EXPECT_EQ(render.classes[5 * 8 + 7], (PixelClass{0, PixelClass::litBit(0)}));
}

TEST(RenderOnCpu, EachLightHasItsOwnBit) {
    // Light 1 is below the floor (seen from behind), light 2 above it: pixel (0, 5) at
    // (-4, 0, 5) is lit by lights 0 and 2.
    Scene scene = groundScene();
    scene.lights.push_back(PointLight{{0, -5, 0}, Color(1.0), 100.0});
    scene.lights.push_back(PointLight{{-4, 3, 5}, Color(1.0), 100.0});
    const CpuRender render = renderOnCpu(scene, 1);
    EXPECT_EQ(render.classes[5 * 8 + 0], (PixelClass{0, PixelClass::litBit(0) | PixelClass::litBit(2)}));
}

TEST(RenderOnCpu, CheckerPixelsInColor2CellsSetTheOddBit) {
    // Squares of 3: pixel (0, 5) lands at (-4, 0, 5), cell (-2, 1), odd; pixel (2, 5) at
    // (-2, 0, 5), cell (-1, 1), even.
    Scene scene = groundScene();
    scene.shaders[0] = CheckerShader{{1, 1, 1}, {0, 0, 0}, 3.0};
    const CpuRender render = renderOnCpu(scene, 1);
    EXPECT_EQ(render.classes[5 * 8 + 0], (PixelClass{0, PixelClass::kOddCheckerBit | PixelClass::litBit(0)}));
    EXPECT_EQ(render.classes[5 * 8 + 2], (PixelClass{0, PixelClass::litBit(0)}));
    EXPECT_FALSE(render.isAmbiguous(5 * 8 + 0));
    EXPECT_FALSE(render.isAmbiguous(5 * 8 + 2));
}

TEST(RenderOnCpu, ConstantShadedPixelsHaveNoFlags) {
    // A constant sphere filling the view, with a light that would reach it: no lights evaluated.
    Scene scene;
    scene.image.width = 8;
    scene.image.height = 6;
    scene.lights.push_back(PointLight{{0, 0, -1}, Color(1.0), 1000.0});
    scene.shaders.push_back(ConstantShader{{2.0, -0.5, 10.0}});
    scene.nodes.push_back(Node{Plane{-100.0}, 0});
    scene.nodes.push_back(Node{Sphere{{0, 0, 10}, 9.9}, 0});
    const CpuRender render = renderOnCpu(scene, 1);
    for (const PixelClass& pixelClass : render.classes) {
        EXPECT_EQ(pixelClass, (PixelClass{1, 0}));
    }
}

TEST(RenderOnCpu, RayAlongThePlaneIsAmbiguousAndOthersAreNot) {
    // Pixel (4, 3) aims exactly parallel to the floor: hit or miss is a coin toss in float32.
    const CpuRender render = renderOnCpu(groundScene(), 1);
    EXPECT_EQ(render.margins[3 * 8 + 4], 0.0f);
    EXPECT_TRUE(render.isAmbiguous(3 * 8 + 4));
    EXPECT_FALSE(render.isAmbiguous(5 * 8 + 0));
    EXPECT_FALSE(render.isAmbiguous(0));
}

TEST(RenderOnCpu, NoNodesMeansNoDecisions) {
    Scene scene = groundScene();
    scene.nodes.clear();
    const CpuRender render = renderOnCpu(scene, 1);
    for (std::size_t pixel = 0; pixel < render.margins.size(); ++pixel) {
        EXPECT_EQ(render.margins[pixel], std::numeric_limits<float>::infinity());
        EXPECT_EQ(render.classes[pixel], (PixelClass{PixelClass::kBackground, 0}));
    }
}

// Far from the origin the reference still resolves a small scene: it traces in the eye's frame.
// From inside a sphere of radius 2e11 whose centre is 3e36 from the origin (the coordinates' rounding
// is 5e20), a light outside it reaches no point; traced in world coordinates every hit rounded onto
// the eye and the sphere's wall lit it.
TEST(RenderOnCpu, ASmallSceneFarFromTheOriginIsResolved) {
    Scene scene;
    scene.image.width = 8;
    scene.image.height = 6;
    scene.camera.position = {1.08e36, -2.64e36, -1.4e36};
    scene.lights.push_back(PointLight{{1.08e36, 0.0, -1.4e36}, Color(1.0), 1e72});
    scene.shaderNames = {"wall"};
    scene.shaders = {LambertShader{Color(1.0)}};
    scene.nodes = {Node{Sphere{scene.camera.position, 2e11}, 0}};
    const CpuRender render = renderOnCpu(scene, 1);
    for (std::size_t i = 0; i < render.classes.size(); ++i) {
        EXPECT_EQ(render.classes[i], (PixelClass{0, 0})) << "pixel " << i;
        EXPECT_EQ(render.image.pixels[i], glm::vec3(0.0f)) << "pixel " << i;
    }
}
