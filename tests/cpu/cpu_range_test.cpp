// The CPU reference across the whole range of lengths the scene loader accepts
// (docs/scene-format.md, "Supported range"): never NaN, unit normals, hit points on the surface.
// Includes the two cases found by the exact oracle (issue 12, findings 2 and 3).

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "cpu/cpu_intersect.h"
#include "cpu/cpu_shading.h"
#include "scene/scene_loader.h"

using namespace hexray;

namespace {

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A scene of one Lambert sphere lit from beside the eye, for shading a hit on it.
Scene litSphereScene(const Sphere& sphere, const glm::dvec3& eye) {
    Scene scene;
    scene.ambient = Color(0.1);
    scene.shaders.push_back(LambertShader{{0.0, 0.5, 1.0}});  // a zero channel: 0 * inf would be NaN
    scene.nodes.push_back(Node{sphere, 0});
    const glm::dvec3 light = eye + glm::dvec3(3.0, 4.0, 0.0) * (sphere.radius + glm::length(sphere.center - eye));
    scene.lights.push_back(PointLight{light, Color(1.0), 1e4});
    return scene;
}

// What every hit of the reference must satisfy, whatever the sphere's size and place.
void expectSoundHit(const Ray& ray, const Sphere& sphere, const std::string& where) {
    const std::optional<Hit> hit = intersectSphere(ray, sphere);
    ASSERT_TRUE(hit) << where;
    EXPECT_TRUE(std::isfinite(hit->t) && hit->t > 0.0) << where << " t " << hit->t;
    ASSERT_TRUE(isFinite(hit->point) && isFinite(hit->geometricNormal) && isFinite(hit->facingNormal)) << where;
    EXPECT_NEAR(glm::length(hit->geometricNormal), 1.0, 1e-14) << where;
    EXPECT_NEAR(glm::length(hit->facingNormal), 1.0, 1e-14) << where;
    // On the sphere to rounding of the coordinates' magnitude.
    const double magnitude =
        std::max({std::abs(sphere.center.x), std::abs(sphere.center.y), std::abs(sphere.center.z)}) + sphere.radius;
    EXPECT_NEAR(glm::length(hit->point - sphere.center), sphere.radius, 1e-14 * magnitude) << where;
    const Scene scene = litSphereScene(sphere, ray.origin);
    const ShadedHit shaded = shadeHit(scene, scene.nodes[0], *hit);
    EXPECT_TRUE(isFinite(shaded.color)) << where << " colour " << shaded.color.x << " " << shaded.color.y;
}

Ray towards(const glm::dvec3& origin, const glm::dvec3& direction) {
    return Ray{origin, glm::normalize(direction)};
}

}  // namespace

// Finding 2: a sphere of radius 1e-20 one unit from the eye. o + t*d - c cancels to 0 (or to
// the wrong side) in double; the normal must come from the intersection's own small terms.
TEST(CpuReferenceRange, TinySphereOneUnitAwayHasTheExactNormal) {
    const Sphere tiny{{0.0, 0.0, 1.0}, 1e-20};
    const std::optional<Hit> centre = intersectSphere(towards({0, 0, 0}, {0, 0, 1}), tiny);
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->geometricNormal.z, -1.0, 1e-15);
    EXPECT_EQ(centre->geometricNormal.x, 0.0);
    expectSoundHit(towards({0, 0, 0}, {0, 0, 1}), tiny, "centre ray");

    // Half a radius off centre: the ray along +z meets the sphere centred 0.5e-20 to its right
    // at the outward normal (-0.5, 0, -sqrt(0.75)).
    const Sphere offCentre{{0.5e-20, 0.0, 1.0}, 1e-20};
    const std::optional<Hit> hit = intersectSphere(towards({0, 0, 0}, {0, 0, 1}), offCentre);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->geometricNormal.x, -0.5, 1e-15);
    EXPECT_NEAR(hit->geometricNormal.y, 0.0, 1e-15);
    EXPECT_NEAR(hit->geometricNormal.z, -std::sqrt(0.75), 1e-15);
}

// Finding 3: the lecture's sphere (radius 10) moved 1e17 away, where an ulp (16) exceeds the
// radius: (p - c) / r from the rounded hit point is not a unit vector.
TEST(CpuReferenceRange, SphereOffsetBy1e17HasUnitNormals) {
    const glm::dvec3 offset(1e17, 1e17, 1e17);
    const Sphere sphere{offset + glm::dvec3(-10, 60, 0), 10.0};
    const glm::dvec3 eye = offset + glm::dvec3(0, 60, -120);
    const glm::dvec3 toCentre = sphere.center - eye;  // exact: both are near 1e17 (the aims are not)
    for (const double aim : {0.0, 3.0, 7.5, 8.9}) {
        expectSoundHit(towards(eye, toCentre + glm::dvec3(aim, aim / 2, 0)), sphere, "aim " + std::to_string(aim));
    }
}

// Radii and offsets across the supported range (every length 0 or 1e-50 ... 1e50 in magnitude),
// seen from near (just outside), from afar (1e12 radii) and from inside, aimed at the centre and
// at half and 0.999 of the radius off it.
TEST(CpuReferenceRange, RadiiAndOffsetsAcrossTheSupportedRange) {
    int checked = 0;
    for (int radiusExponent = -50; radiusExponent <= 50; radiusExponent += 5) {
        const double radius = std::pow(10.0, radiusExponent) * 1.37;
        for (int offsetExponent = -50; offsetExponent <= 50; offsetExponent += 10) {
            for (const double sign : {1.0, -1.0}) {
                const double offset = std::min(sign * std::pow(10.0, offsetExponent), kMaxSceneLength / 2);
                const glm::dvec3 center(offset, -0.5 * offset, 0.25 * offset);
                for (const double distance : {1.5 * radius, 1e12 * radius, 0.3 * radius}) {
                    if (std::abs(offset) + distance > kMaxSceneLength)
                        continue;
                    const glm::dvec3 eye = center - glm::dvec3(0.0, 0.0, distance);
                    for (const double aim : {0.0, 0.5, 0.999}) {
                        const glm::dvec3 target = center + glm::dvec3(aim * radius, 0.0, 0.0);
                        if (target - eye == glm::dvec3(0.0))
                            continue;
                        const Ray ray = towards(eye, target - eye);
                        if (!intersectSphere(ray, Sphere{center, radius}))
                            continue;  // aim lost to rounding
                        expectSoundHit(ray, Sphere{center, radius},
                                       "radius " + std::to_string(radius) + " offset " + std::to_string(offset) +
                                           " distance " + std::to_string(distance) + " aim " + std::to_string(aim));
                        ++checked;
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

// Planes across the range: the hit is on the plane, the normal is a unit axis, the colour finite.
TEST(CpuReferenceRange, PlanesAcrossTheSupportedRange) {
    int checked = 0;
    for (int exponent = -50; exponent <= 50; exponent += 5) {
        for (const double sign : {1.0, -1.0}) {
            const double height = sign * std::pow(10.0, exponent);
            for (const double above : {std::pow(10.0, exponent - 3), std::pow(10.0, exponent)}) {
                const glm::dvec3 eye(height, height + above, -height);
                const Ray ray = towards(eye, {0.3, -1.0, 0.2});
                const std::optional<Hit> hit = intersectPlane(ray, Plane{height});
                ASSERT_TRUE(hit) << height;
                EXPECT_EQ(hit->point.y, height);
                EXPECT_TRUE(isFinite(hit->point) && std::isfinite(hit->t));
                EXPECT_EQ(hit->facingNormal, glm::dvec3(0, 1, 0));
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 84);
}
