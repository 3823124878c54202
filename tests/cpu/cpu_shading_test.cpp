// Shading of the CPU reference: checker cells, texture coordinates, Lambert light, shadows.
// Expected values are computed by hand from the model, not taken from the code.

#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "cpu/cpu_intersect.h"
#include "cpu/cpu_shading.h"

using namespace hexray;

namespace {

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expectNear(const glm::dvec2& actual, const glm::dvec2& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

// A hit on the plane y = 0 at (x, 0, z), seen from above.
Hit planeHitFromAbove(double x, double z) {
    Hit hit;
    hit.t = 1.0;
    hit.point = {x, 0.0, z};
    hit.geometricNormal = {0, 1, 0};
    hit.facingNormal = {0, 1, 0};
    return hit;
}

PointLight lightAt(const glm::dvec3& position, double intensity, const Color& color = Color(1.0)) {
    return PointLight{position, color, intensity};
}

const Geometry kGround = Plane{0.0};

}  // namespace

// ---------------------------------------------------------------- checker

TEST(CheckerParity, CellsAroundTheOrigin) {
    // Size 20: (0.5, 0.5) is cell (0, 0); (-0.5, 0.5) is (-1, 0); (-0.5, -0.5) is (-1, -1).
    EXPECT_EQ(checkerParity(0.5, 0.5, 20), 0);
    EXPECT_EQ(checkerParity(-0.5, 0.5, 20), 1);
    EXPECT_EQ(checkerParity(0.5, -0.5, 20), 1);
    EXPECT_EQ(checkerParity(-0.5, -0.5, 20), 0);
    // (-20.1, 39.9) is cell (-2, 1): odd.
    EXPECT_EQ(checkerParity(-20.1, 39.9, 20), 1);
    // Cell edges belong to the cell above them: floor(20/20) = 1.
    EXPECT_EQ(checkerParity(20.0, 0.0, 20), 1);
    EXPECT_EQ(checkerParity(-20.0, 0.0, 20), 1);  // cell -1
    EXPECT_EQ(checkerParity(-40.0, 0.0, 20), 0);  // cell -2
}

TEST(CheckerParity, AlternatesThroughNegativeCoordinates) {
    // Walking u in unit cells from -10.5 to 9.5 must flip parity at every step.
    for (int i = -10; i < 10; ++i) {
        const double u = i + 0.5;
        EXPECT_NE(checkerParity(u, 0.25, 1.0), checkerParity(u + 1.0, 0.25, 1.0)) << "u = " << u;
        EXPECT_NE(checkerParity(0.25, u, 1.0), checkerParity(0.25, u + 1.0, 1.0)) << "v = " << u;
    }
}

TEST(CheckerParity, LargeCoordinates) {
    // 1e7 / 20 = 500000, even; one cell further is odd.
    EXPECT_EQ(checkerParity(1e7, 0.5, 20), 0);
    EXPECT_EQ(checkerParity(1e7 + 20, 0.5, 20), 1);
    EXPECT_EQ(checkerParity(-1e7 - 10, 0.5, 20), 1);      // cell -500001
    EXPECT_EQ(checkerParity(1e7 + 10, 1e7 + 30, 20), 1);  // 500000 + 500001
    // The largest odd integer a double holds exactly, 2^53 - 1.
    const double largestOdd = 9007199254740991.0;
    EXPECT_EQ(checkerParity(largestOdd, 0.5, 1), 1);
    EXPECT_EQ(checkerParity(-largestOdd, 0.5, 1), 1);
}

TEST(CheckerParity, BeyondTheRangeOfInt64) {
    // Doubles this large are even integers; a cast to int64 would be undefined behaviour.
    EXPECT_EQ(checkerParity(1e20, 0.5, 1), 0);
    EXPECT_EQ(checkerParity(-1e30, 0.5, 1), 0);
    EXPECT_EQ(checkerParity(1e300, 1.5, 1), 1);  // even + cell 1
    EXPECT_EQ(checkerParity(-1e300, -1e300, 1), 0);
}

TEST(CheckerColor, PicksColor1OnEvenCells) {
    const CheckerShader checker{Color(1, 0, 0), Color(0, 0, 1), 9.0};
    expectNear(checkerColor(checker, {4.5, 4.5}), {1, 0, 0}, 0.0);
    expectNear(checkerColor(checker, {13.5, 4.5}), {0, 0, 1}, 0.0);
    expectNear(checkerColor(checker, {-4.5, 4.5}), {0, 0, 1}, 0.0);
}

// ---------------------------------------------------------------- texture coordinates

TEST(TextureCoordinates, PlaneUsesXAndZ) {
    expectNear(planeTextureCoordinates({3.5, 0.0, -7.25}), {3.5, -7.25}, 0.0);
    expectNear(textureCoordinates(kGround, planeHitFromAbove(-1.5, 2.5)), {-1.5, 2.5}, 0.0);
}

TEST(TextureCoordinates, SphereLongitudeLatitudeInDegrees) {
    expectNear(sphereTextureCoordinates({0, 0, 1}), {0, 0}, 1e-12);
    expectNear(sphereTextureCoordinates({1, 0, 0}), {90, 0}, 1e-12);
    expectNear(sphereTextureCoordinates({-1, 0, 0}), {-90, 0}, 1e-12);
    expectNear(sphereTextureCoordinates({0, 0, -1}), {180, 0}, 1e-12);
    expectNear(sphereTextureCoordinates({0, 1, 0}), {0, 90}, 1e-12);
    expectNear(sphereTextureCoordinates({0, -1, 0}), {0, -90}, 1e-12);
    // n = (0.5, sqrt(0.5), 0.5): longitude atan2(0.5, 0.5) = 45, latitude asin(sqrt(0.5)) = 45.
    expectNear(sphereTextureCoordinates({0.5, std::sqrt(0.5), 0.5}), {45, 45}, 1e-12);
    // 30 degrees north, 60 degrees west: (-cos30 sin60, sin30, cos30 cos60).
    const double c30 = std::sqrt(3.0) / 2.0;
    expectNear(sphereTextureCoordinates({-c30 * c30, 0.5, c30 * 0.5}), {-60, 30}, 1e-12);
}

TEST(TextureCoordinates, SpherePoleRoundingGivesNoNaN) {
    const glm::dvec2 uv = sphereTextureCoordinates({0, 1.0 + 2e-16, 0});
    EXPECT_DOUBLE_EQ(uv.y, 90.0);
}

TEST(TextureCoordinates, SphereSeenFromInsideUsesTheOutwardNormal) {
    // Looking along -X from inside: the outward normal is (-1, 0, 0), longitude -90
    // (the facing normal (1, 0, 0) would say +90).
    const Geometry sphere = Sphere{{0, 0, 0}, 5};
    const std::optional<Hit> hit = intersectSphere(Ray{{0, 0, 0}, {-1, 0, 0}}, std::get<Sphere>(sphere));
    ASSERT_TRUE(hit);
    expectNear(textureCoordinates(sphere, *hit), {-90, 0}, 1e-12);
}

// ---------------------------------------------------------------- Lambert light

TEST(Lambert, NormalIncidenceAtDistance100WithIntensity10000IsOne) {
    Scene scene;
    scene.lights.push_back(lightAt({0, 100, 0}, 10000));
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {1, 1, 1}, 1e-15);
    expectNear(Color(0.2, 0.4, 0.8) * incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {0.2, 0.4, 0.8}, 1e-15);
}

TEST(Lambert, SixtyDegreesGivesHalf) {
    // Light 100 away, 60 degrees from the normal: (100 sin 60, 100 cos 60, 0) = (86.60..., 50, 0).
    Scene scene;
    const double angle = std::numbers::pi / 3.0;
    scene.lights.push_back(lightAt({100 * std::sin(angle), 100 * std::cos(angle), 0}, 10000));
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {0.5, 0.5, 0.5}, 1e-14);
}

TEST(Lambert, AmbientAndLightColourAndFalloff) {
    // Light at (3, 4, 0) from the hit at the origin: r = 5, cos = 4/5, intensity 50:
    // 50 * 0.8 / 25 = 1.6, times colour (1, 0.5, 0.25); plus ambient (0.1, 0.2, 0.3).
    Scene scene;
    scene.ambient = {0.1, 0.2, 0.3};
    scene.lights.push_back(lightAt({3, 4, 0}, 50, {1, 0.5, 0.25}));
    const Color expectedLight(0.1 + 1.6, 0.2 + 0.8, 0.3 + 0.4);
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), expectedLight, 1e-14);
    const Color albedo(0.5, 1.0, 2.0);
    expectNear(albedo * incidentLight(scene, kGround, planeHitFromAbove(0, 0)), albedo * expectedLight, 1e-14);
}

TEST(Lambert, LightsAddUp) {
    Scene scene;
    scene.ambient = Color(0.15);
    scene.lights.push_back(lightAt({0, 100, 0}, 10000));         // 1.0
    scene.lights.push_back(lightAt({0, 10, 0}, 25, {0, 1, 0}));  // 0.25 green
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {1.15, 1.4, 1.15}, 1e-14);
}

TEST(Lambert, LightBehindTheSurfaceGivesOnlyAmbient) {
    Scene scene;
    scene.ambient = Color(0.15);
    scene.lights.push_back(lightAt({0, -10, 0}, 10000));  // below a point seen from above
    scene.lights.push_back(lightAt({10, 0, 0}, 10000));   // in the plane: cos = 0
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {0.15, 0.15, 0.15}, 0.0);
}

TEST(Lambert, LightOnThePointContributesNothing) {
    Scene scene;
    scene.lights.push_back(lightAt({2, 0, 3}, 10000));
    const Color light = incidentLight(scene, kGround, planeHitFromAbove(2, 3));
    expectNear(light, {0, 0, 0}, 0.0);  // not NaN
}

TEST(Lambert, SphereLitFromInside) {
    // Camera and light at the centre of a radius-10 sphere: every point faces the light
    // with cos = 1 at r = 10, so intensity 100 gives 1 and the sphere does not shadow itself.
    Scene scene;
    const Geometry sphere = Sphere{{1, 2, 3}, 10};
    scene.nodes.push_back(Node{sphere, 0});
    scene.lights.push_back(lightAt({1, 2, 3}, 100));
    for (const glm::dvec3& direction : {glm::dvec3(0, 0, 1), glm::dvec3(1, -2, 2) / 3.0}) {
        const std::optional<Hit> hit = intersectSphere(Ray{{1, 2, 3}, direction}, std::get<Sphere>(sphere));
        ASSERT_TRUE(hit);
        expectNear(incidentLight(scene, sphere, *hit), {1, 1, 1}, 1e-14);
    }
}

// ---------------------------------------------------------------- shadows

TEST(Shadow, OccluderBetweenPointAndLight) {
    // Plane y = 0, sphere of radius 10 at (0, 50, 0), light at (0, 100, 0): the origin is in
    // shadow; (60, 0, 0) is not (its line to the light passes 25.7 from the centre).
    Scene scene;
    scene.ambient = Color(0.15);
    scene.shaders.push_back(LambertShader{Color(1.0)});
    scene.nodes.push_back(Node{kGround, 0});
    scene.nodes.push_back(Node{Sphere{{0, 50, 0}, 10}, 0});
    scene.lights.push_back(lightAt({0, 100, 0}, 10000));

    EXPECT_FALSE(isLightVisible(scene, kGround, planeHitFromAbove(0, 0), {0, 100, 0}));
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(0, 0)), {0.15, 0.15, 0.15}, 0.0);

    EXPECT_TRUE(isLightVisible(scene, kGround, planeHitFromAbove(60, 0), {0, 100, 0}));
    // r^2 = 60^2 + 100^2 = 13600, cos = 100 / sqrt(13600).
    const double expected = 0.15 + 10000.0 * (100.0 / std::sqrt(13600.0)) / 13600.0;
    expectNear(incidentLight(scene, kGround, planeHitFromAbove(60, 0)), Color(expected), 1e-14);
}

TEST(Shadow, OccluderBeyondTheLightDoesNotShadow) {
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    scene.nodes.push_back(Node{kGround, 0});
    scene.nodes.push_back(Node{Sphere{{0, 200, 0}, 10}, 0});
    EXPECT_TRUE(isLightVisible(scene, kGround, planeHitFromAbove(0, 0), {0, 100, 0}));
}

TEST(Shadow, PlaneNeedsNoOffset) {
    // The snapped point cannot hit its own plane: t would be exactly 0.
    EXPECT_EQ(shadowRayOffset(kGround), 0.0);
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    scene.nodes.push_back(Node{Plane{0.1}, 0});
    const std::optional<Hit> hit =
        intersectPlane(Ray{{0.3, 1e4, 0.7}, glm::normalize(glm::dvec3(0.1, -1, 0.2))}, Plane{0.1});
    ASSERT_TRUE(hit);
    EXPECT_TRUE(isLightVisible(scene, Plane{0.1}, *hit, {1e4, 0.1 + 1e-9, -3e4}));  // nearly grazing
}

TEST(Shadow, SphereOffsetScalesWithCoordinates) {
    const double small = shadowRayOffset(Sphere{{0, 0, 0}, 1});
    const double large = shadowRayOffset(Sphere{{1e6, 0, 0}, 1});
    EXPECT_GT(small, 0.0);
    EXPECT_GT(large, 1e5 * small);
    // Still far below anything visible: a few ulp, not a fixed epsilon.
    EXPECT_LT(large, 1e-8);
    // Always several ulp of the largest coordinate a hit point can have (|c_i| + r), so the
    // rounding of p + offset * n cannot undo it; also when p itself is near 0.
    for (double scale : {1e-3, 1.0, 1e3, 1e6, 1e9}) {
        const Sphere sphere{{scale, -scale, scale}, scale};
        const double largestCoordinate = 2 * scale;
        const double ulp = std::nextafter(largestCoordinate, INFINITY) - largestCoordinate;
        EXPECT_GE(shadowRayOffset(sphere), 4 * ulp) << scale;
    }
}

namespace {

// Shoots rays from outside (or inside) at a sphere, then sends a shadow ray from each lit hit to
// a light on the lit side. The sphere is convex, so it must never shadow its own lit side.
// Returns {self-shadowed count, lit hits tried}.
std::pair<int, int> countSelfShadowing(const Sphere& sphere, bool fromInside, bool withOffset) {
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    scene.nodes.push_back(Node{sphere, 0});
    const Geometry geometry = sphere;
    int selfShadowed = 0;
    int tried = 0;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            const glm::dvec3 target =
                sphere.center + sphere.radius * 0.95 * glm::dvec3((i - 19.5) / 20.0, (j - 19.5) / 20.0, -0.3);
            const glm::dvec3 origin = fromInside ? sphere.center + glm::dvec3(0.1, -0.2, 0.3) * sphere.radius
                                                 : sphere.center + glm::dvec3(0.3, 0.2, -10.0) * sphere.radius;
            const glm::dvec3 direction = glm::normalize(fromInside ? origin - target : target - origin);
            const std::optional<Hit> hit = intersectSphere(Ray{origin, direction}, sphere);
            if (!hit) {
                continue;
            }
            // A light along a direction tilted from the facing normal, at grazing angles too.
            const glm::dvec3 tangent = glm::normalize(glm::cross(hit->facingNormal, glm::dvec3(0.3, 0.7, 0.1)));
            const double tilt = 0.2 + 1.35 * double((i * 40 + j) % 97) / 96.0;  // up to ~87 degrees
            const glm::dvec3 toLight = std::cos(tilt) * hit->facingNormal + std::sin(tilt) * tangent;
            const double lightDistance = fromInside ? 0.01 * sphere.radius : 3.0 * sphere.radius;
            const glm::dvec3 light = hit->point + lightDistance * toLight;
            ++tried;
            const bool visible = withOffset ? isLightVisible(scene, geometry, *hit, light)
                                            : isSegmentClear(scene, hit->point, light, 0.0);
            if (!visible) {
                ++selfShadowed;
            }
        }
    }
    return {selfShadowed, tried};
}

}  // namespace

TEST(Shadow, NoSelfShadowingOnSpheresAtAnyScale) {
    for (const glm::dvec3& center :
         {glm::dvec3(0, 0, 0), glm::dvec3(1e3, -2e3, 5e2), glm::dvec3(1e6, 1e6, -1e6), glm::dvec3(-3e8, 1e7, 2e8)}) {
        for (double radius : {1e-3, 1.0, 250.0}) {
            const Sphere sphere{center, radius};
            for (bool fromInside : {false, true}) {
                const auto [selfShadowed, tried] = countSelfShadowing(sphere, fromInside, true);
                EXPECT_GT(tried, 100);
                EXPECT_EQ(selfShadowed, 0)
                    << "centre " << center.x << " radius " << radius << (fromInside ? " inside" : " outside");
            }
        }
    }
}

TEST(Shadow, WithoutTheOffsetSpheresDoShadowThemselves) {
    // The control for the test above: with no offset the same rays report acne, so that test
    // would catch an offset that is too small.
    int total = 0;
    for (const glm::dvec3& center : {glm::dvec3(0, 0, 0), glm::dvec3(1e6, 1e6, -1e6)}) {
        total += countSelfShadowing(Sphere{center, 1.0}, false, false).first;
        total += countSelfShadowing(Sphere{center, 1.0}, true, false).first;
    }
    EXPECT_GT(total, 0);
}

TEST(Shadow, LightOnTheSphereSurfaceIsNotBlockedByIt) {
    // From inside a sphere, a light exactly on its inner surface is visible from every point
    // facing it: the segment ends on the surface, which the shortened distance excludes.
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    const Sphere sphere{{10, 20, 30}, 5};
    scene.nodes.push_back(Node{sphere, 0});
    const glm::dvec3 light = sphere.center + glm::dvec3(0, 5, 0);
    int blocked = 0;
    for (int i = 0; i < 50; ++i) {
        const glm::dvec3 direction = glm::normalize(glm::dvec3(std::sin(i * 0.9), -1.0 + 0.03 * i, std::cos(i * 1.7)));
        const std::optional<Hit> hit = intersectSphere(Ray{sphere.center, direction}, sphere);
        ASSERT_TRUE(hit);
        if (!isLightVisible(scene, sphere, *hit, light)) {
            ++blocked;
        }
    }
    EXPECT_EQ(blocked, 0);
}

TEST(Shadow, SphereSeenFromInsideBlocksALightJustOutsideIt) {
    // Far from the origin the shadow ray's offset (3.6e-9 here) exceeds the light's distance from
    // the sphere (2e-9): every point that faces the light must still find it blocked (convexity).
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    const Sphere sphere{{1e6, -2e6, 5e5}, 1};
    scene.nodes.push_back(Node{sphere, 0});
    const glm::dvec3 light = sphere.center + glm::dvec3(0, 1 + 2e-9, 0);
    ASSERT_GT(glm::length(light - sphere.center), sphere.radius);
    int facing = 0;
    int lit = 0;
    for (int i = 0; i < 50; ++i) {
        const glm::dvec3 direction = glm::normalize(glm::dvec3(std::sin(i * 0.9), -1.0 + 0.04 * i, std::cos(i * 1.7)));
        const std::optional<Hit> hit = intersectSphere(Ray{sphere.center, direction}, sphere);
        ASSERT_TRUE(hit);
        if (glm::dot(hit->facingNormal, light - hit->point) > 0.0) {
            ++facing;
            lit += isLightVisible(scene, sphere, *hit, light) ? 1 : 0;
        }
    }
    EXPECT_GT(facing, 40);
    EXPECT_EQ(lit, 0);
}

TEST(Shadow, SegmentClearBasics) {
    Scene scene;
    scene.shaders.push_back(LambertShader{});
    scene.nodes.push_back(Node{Sphere{{0, 0, 5}, 1}, 0});
    EXPECT_FALSE(isSegmentClear(scene, {0, 0, 0}, {0, 0, 10}, 0.0));
    EXPECT_TRUE(isSegmentClear(scene, {0, 0, 0}, {0, 0, 3.9}, 0.0));  // stops before the sphere at 4
    EXPECT_TRUE(isSegmentClear(scene, {0, 0, 0}, {0, 0, 10}, 20.0));  // shortened to nothing
    EXPECT_TRUE(isSegmentClear(scene, {0, 0, 0}, {0, 0, 0}, 0.0));    // zero length
}

// ---------------------------------------------------------------- shader dispatch

TEST(ShadeHit, ConstantIgnoresLightsAndAmbient) {
    Scene scene;
    scene.ambient = Color(0.5);
    scene.lights.push_back(lightAt({0, 10, 0}, 1e6));
    scene.shaders.push_back(ConstantShader{{0.25, 0.5, 0.75}});
    scene.nodes.push_back(Node{kGround, 0});
    expectNear(shadeHit(scene, scene.nodes[0], planeHitFromAbove(1, 2)).color, {0.25, 0.5, 0.75}, 0.0);
}

TEST(ShadeHit, LambertAndChecker) {
    Scene scene;
    scene.ambient = Color(0.25);
    scene.lights.push_back(lightAt({0, 100, 0}, 10000));  // 1.0 at the origin, cos = 1
    scene.shaders.push_back(LambertShader{{0.2, 0.4, 0.6}});
    scene.shaders.push_back(CheckerShader{{1, 0, 0}, {0, 0, 1}, 1.0});
    scene.nodes.push_back(Node{kGround, 0});
    scene.nodes.push_back(Node{kGround, 1});
    expectNear(shadeHit(scene, scene.nodes[0], planeHitFromAbove(0, 0)).color, {0.25, 0.5, 0.75}, 1e-15);
    // (0.5, 0.5) is an even cell: color1; (-0.5, 0.5) odd: color2. r^2 = 0.25 + 10000 + 0.25.
    const double light = 0.25 + 10000.0 * (100.0 / std::sqrt(10000.5)) / 10000.5;
    expectNear(shadeHit(scene, scene.nodes[1], planeHitFromAbove(0.5, 0.5)).color, {light, 0, 0}, 1e-14);
    expectNear(shadeHit(scene, scene.nodes[1], planeHitFromAbove(-0.5, 0.5)).color, {0, 0, light}, 1e-14);
}
