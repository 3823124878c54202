// Ray/plane and ray/sphere intersection of the CPU reference, against geometry solved by hand.

#include <cmath>
#include <limits>
#include <optional>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "cpu/cpu_intersect.h"

using namespace hexray;

namespace {

Ray rayFrom(const glm::dvec3& origin, const glm::dvec3& toward) {
    return Ray{origin, glm::normalize(toward)};
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Sphere sphereAt(const glm::dvec3& center, double radius) {
    return Sphere{center, radius};
}

}  // namespace

// ---------------------------------------------------------------- plane

TEST(IntersectPlane, StraightDownFromAbove) {
    const std::optional<Hit> hit = intersectPlane(rayFrom({0, 5, 0}, {0, -1, 0}), Plane{0.0});
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 5.0);
    expectNear(hit->point, {0, 0, 0}, 0.0);
    expectNear(hit->facingNormal, {0, 1, 0}, 0.0);
    expectNear(hit->geometricNormal, {0, 1, 0}, 0.0);
}

TEST(IntersectPlane, ObliqueFromAbove345) {
    // Direction (3, -4, 0)/5 from height 4 travels 5 to reach y = 0 at x = 3.
    const std::optional<Hit> hit = intersectPlane(rayFrom({0, 4, 1}, {3, -4, 0}), Plane{0.0});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-14);
    expectNear(hit->point, {3, 0, 1}, 1e-14);
}

TEST(IntersectPlane, FromBelowFacesDown) {
    const std::optional<Hit> hit = intersectPlane(rayFrom({2, -2, 7}, {0, 1, 0}), Plane{1.0});
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 3.0);
    expectNear(hit->point, {2, 1, 7}, 0.0);
    expectNear(hit->facingNormal, {0, -1, 0}, 0.0);
    expectNear(hit->geometricNormal, {0, 1, 0}, 0.0);
}

TEST(IntersectPlane, MissesWhenGoingAway) {
    EXPECT_FALSE(intersectPlane(rayFrom({0, 5, 0}, {1, 1, 0}), Plane{0.0}));    // above, going up
    EXPECT_FALSE(intersectPlane(rayFrom({0, -5, 0}, {1, -1, 0}), Plane{0.0}));  // below, going down
}

TEST(IntersectPlane, ParallelMissesForBothSignedZeros) {
    EXPECT_FALSE(intersectPlane(Ray{{0, 5, 0}, {1, +0.0, 0}}, Plane{0.0}));
    EXPECT_FALSE(intersectPlane(Ray{{0, 5, 0}, {1, -0.0, 0}}, Plane{0.0}));
    EXPECT_FALSE(intersectPlane(Ray{{0, -5, 0}, {0, -0.0, 1}}, Plane{0.0}));
    // Lying in the plane: 0/0 would be NaN.
    EXPECT_FALSE(intersectPlane(Ray{{0, 0, 0}, {1, +0.0, 0}}, Plane{0.0}));
    EXPECT_FALSE(intersectPlane(Ray{{0, 0, 0}, {1, -0.0, 0}}, Plane{0.0}));
}

TEST(IntersectPlane, StartingOnThePlaneIsNotAHit) {
    // t would be exactly 0: a camera in the plane does not see it.
    EXPECT_FALSE(intersectPlane(rayFrom({3, 2, 1}, {0, -1, 1}), Plane{2.0}));
    EXPECT_FALSE(intersectPlane(rayFrom({3, 2, 1}, {0, 1, 1}), Plane{2.0}));
}

TEST(IntersectPlane, JustAboveThePlaneStillHits) {
    // Camera rays accept any t > 0: no minimum distance.
    const std::optional<Hit> hit = intersectPlane(rayFrom({0, 1e-9, 0}, {0, -1, 0}), Plane{0.0});
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 1e-9);
}

TEST(IntersectPlane, DenormalDirectionOverflowIsAMiss) {
    // (0 - 1) / -5e-324 overflows to +inf: not a hit at infinity.
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_FALSE(intersectPlane(Ray{{0, 1, 0}, {1, -tiny, 0}}, Plane{0.0}));
}

TEST(IntersectPlane, HitPointIsSnappedOntoThePlane) {
    // o + t*d would round off the plane; the hit point's y must be the height exactly.
    const Plane plane{0.1};
    for (int i = 1; i <= 50; ++i) {
        const Ray ray = rayFrom({0.3 * i, 12345.678 + i, -7.1 * i}, {0.37, -0.011 * i, 0.93});
        const std::optional<Hit> hit = intersectPlane(ray, plane);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->point.y, 0.1);
    }
}

// ---------------------------------------------------------------- sphere

TEST(IntersectSphere, FromOutsideHitsAtDistanceMinusRadius) {
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 0, 10}, 2));
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 8.0);
    expectNear(hit->point, {0, 0, 8}, 1e-15);
    expectNear(hit->geometricNormal, {0, 0, -1}, 1e-15);
    expectNear(hit->facingNormal, {0, 0, -1}, 1e-15);
}

TEST(IntersectSphere, ObliqueFromOutside) {
    // Ray along +Z at x = 3 meets a radius-5 sphere at the origin where z = -4.
    const std::optional<Hit> hit = intersectSphere(rayFrom({3, 0, -20}, {0, 0, 1}), sphereAt({0, 0, 0}, 5));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 16.0, 1e-14);
    expectNear(hit->point, {3, 0, -4}, 1e-14);
    expectNear(hit->geometricNormal, {0.6, 0, -0.8}, 1e-15);
}

TEST(IntersectSphere, FromInsideTakesTheFarRoot) {
    // From (0, 1, 0) along +Z inside radius 3: z = sqrt(9 - 1) = sqrt(8).
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 1, 0}, {0, 0, 1}), sphereAt({0, 0, 0}, 3));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(8.0), 1e-15);
    const glm::dvec3 outward(0, 1.0 / 3.0, std::sqrt(8.0) / 3.0);
    expectNear(hit->geometricNormal, outward, 1e-15);
    expectNear(hit->facingNormal, -outward, 1e-15);  // seen from inside it faces inward
}

TEST(IntersectSphere, FromTheCentreHitsAtTheRadius) {
    const std::optional<Hit> hit = intersectSphere(rayFrom({4, 5, 6}, {1, 2, 2}), sphereAt({4, 5, 6}, 7));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 7.0, 1e-14);
    expectNear(hit->point, {4 + 7.0 / 3, 5 + 14.0 / 3, 6 + 14.0 / 3}, 1e-14);
}

TEST(IntersectSphere, BehindTheRayMisses) {
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 0, -10}, 2)));
}

TEST(IntersectSphere, ClearMiss) {
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 5, 10}, 2)));
}

TEST(IntersectSphere, GrazingNearMissAndNearHit) {
    // The ray y = 0 along +Z passes the centre at distance 1 +- 1e-9 from a unit sphere.
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 1 + 1e-9, 10}, 1)));
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 1 - 1e-9, 10}, 1));
    ASSERT_TRUE(hit);
    // Half chord sqrt(1 - (1 - 1e-9)^2) = sqrt(2e-9 - 1e-18).
    EXPECT_NEAR(hit->t, 10.0 - std::sqrt(2e-9 - 1e-18), 1e-10);
}

TEST(IntersectSphere, ExactTangentHits) {
    // Touching at one point: discriminant exactly 0, one root at the centre's depth.
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 1, 10}, 1));
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 10.0);
}

TEST(IntersectSphere, TinySphereFarAwayOnAxis) {
    // r = 1 at D = 1e7: t = D - r exactly; the textbook discriminant has no digits left here in float.
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 0, 0}, {0, 0, 1}), sphereAt({0, 0, 1e7}, 1));
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 1e7 - 1);
}

TEST(IntersectSphere, TinySphereFarAwayOffAxis) {
    // The ray aims at (0, 0.6, 1e7): it passes the centre at distance 0.6 * (1 - ~2e-15), so the
    // half chord is sqrt(1 - 0.36) = 0.8 and the hit is 0.8 before the closest point.
    // In double, |f|^2 - b'^2 would lose ~1e-2 of the discriminant here and t by ~6e-3.
    const double distanceToClosestPoint = 1e14 / std::sqrt(1e14 + 0.36);  // dot(c, d)
    const std::optional<Hit> hit = intersectSphere(rayFrom({0, 0, 0}, {0, 0.6, 1e7}), sphereAt({0, 0, 1e7}, 1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, distanceToClosestPoint - 0.8, 1e-7);
    expectNear(hit->point, {0, 0.6, 1e7 - 0.8}, 1e-7);
    expectNear(hit->geometricNormal, {0, 0.6, -0.8}, 1e-7);
}

TEST(IntersectSphere, TinySphereFarAwayRimDecidedCorrectly) {
    // Aiming 1e-6 inside and outside the rim of a unit sphere 1e7 away.
    EXPECT_TRUE(intersectSphere(rayFrom({0, 0, 0}, {0, 1 - 1e-6, 1e7}), sphereAt({0, 0, 1e7}, 1)));
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 0}, {0, 1 + 1e-6, 1e7}), sphereAt({0, 0, 1e7}, 1)));
}

TEST(IntersectSphere, RayStartingOnTheSurface) {
    // Going in: the far side, a diameter away. Going out: nothing (the root at 0 is not a hit).
    const Sphere unit = sphereAt({0, 0, 0}, 1);
    const std::optional<Hit> in = intersectSphere(rayFrom({0, 0, -1}, {0, 0, 1}), unit);
    ASSERT_TRUE(in);
    EXPECT_DOUBLE_EQ(in->t, 2.0);
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, 1}, {0, 0, 1}), unit));
    // Tangent from a point on the surface: both roots 0 (q = 0), a miss and no NaN.
    EXPECT_FALSE(intersectSphere(rayFrom({0, 0, -1}, {1, 0, 0}), unit));
}

TEST(IntersectSphere, HitPointLiesOnTheSphereFarFromTheOrigin) {
    // Reprojection keeps |p - c| = r to rounding of the coordinates, even where o + t*d would not.
    const Sphere sphere = sphereAt({1e5, -3e5, 2e5}, 0.25);
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 jitter(0.15 * std::sin(i * 1.3), 0.15 * std::cos(i * 0.7), 0.0);  // |jitter| < r
        const glm::dvec3 origin = sphere.center + glm::dvec3(-30, 40, -1000);
        const Ray ray = rayFrom(origin, sphere.center + jitter - origin);
        const std::optional<Hit> hit = intersectSphere(ray, sphere);
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(glm::length(hit->point - sphere.center), 0.25, 1e-10) << i;
        EXPECT_NEAR(glm::length(hit->geometricNormal), 1.0, 1e-9) << i;
    }
}

// ---------------------------------------------------------------- nearest hit

namespace {

Scene sceneWith(std::initializer_list<Geometry> geometries) {
    Scene scene;
    scene.shaders.push_back(ConstantShader{});
    for (const Geometry& geometry : geometries) {
        scene.nodes.push_back(Node{geometry, 0});
    }
    return scene;
}

}  // namespace

TEST(FindNearestHit, EmptySceneAndAllMissesGiveNothing) {
    const Ray ray = rayFrom({0, 0, 0}, {0, 0, 1});
    EXPECT_FALSE(findNearestHit(ray, Scene{}));
    EXPECT_FALSE(findNearestHit(ray, sceneWith({sphereAt({0, 0, -5}, 1), Plane{-1.0}})));
}

TEST(FindNearestHit, NearerNodeWinsInEitherOrder) {
    const Ray ray = rayFrom({0, 0, 0}, {0, 0, 1});
    const Geometry near = sphereAt({0, 0, 5}, 1);
    const Geometry far = sphereAt({0, 0, 20}, 3);
    const std::optional<SceneHit> a = findNearestHit(ray, sceneWith({far, near}));
    ASSERT_TRUE(a);
    EXPECT_EQ(a->nodeIndex, 1u);
    EXPECT_DOUBLE_EQ(a->hit.t, 4.0);
    const std::optional<SceneHit> b = findNearestHit(ray, sceneWith({near, far}));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->nodeIndex, 0u);
    EXPECT_DOUBLE_EQ(b->hit.t, 4.0);
}

TEST(FindNearestHit, PlaneInFrontOfSphere) {
    // Looking down from y = 5 at a plane y = 2 with a sphere below it.
    const Ray ray = rayFrom({0, 5, 0}, {0, -1, 0});
    const std::optional<SceneHit> hit = findNearestHit(ray, sceneWith({sphereAt({0, -3, 0}, 1), Plane{2.0}}));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->nodeIndex, 1u);
    EXPECT_DOUBLE_EQ(hit->hit.t, 3.0);
}

TEST(FindNearestHit, ExactTieGoesToTheEarlierNode) {
    // A sphere of radius 1 centred at (0, -1, 0) touches the plane y = 0 at the origin; the ray
    // straight down from y = 5 reaches both at t = 5 exactly (sphere: c'/q = 35/7).
    const Ray ray = rayFrom({0, 5, 0}, {0, -1, 0});
    const Geometry sphere = sphereAt({0, -1, 0}, 1);
    const Geometry plane = Plane{0.0};
    ASSERT_EQ(intersectSphere(ray, std::get<Sphere>(sphere))->t, 5.0);
    ASSERT_EQ(intersectPlane(ray, std::get<Plane>(plane))->t, 5.0);

    const std::optional<SceneHit> sphereFirst = findNearestHit(ray, sceneWith({sphere, plane}));
    ASSERT_TRUE(sphereFirst);
    EXPECT_EQ(sphereFirst->nodeIndex, 0u);
    const std::optional<SceneHit> planeFirst = findNearestHit(ray, sceneWith({plane, sphere}));
    ASSERT_TRUE(planeFirst);
    EXPECT_EQ(planeFirst->nodeIndex, 0u);
    // Identical geometry: the first copy.
    const std::optional<SceneHit> twins = findNearestHit(ray, sceneWith({Plane{-7.0}, plane, plane}));
    ASSERT_TRUE(twins);
    EXPECT_EQ(twins->nodeIndex, 1u);
}
