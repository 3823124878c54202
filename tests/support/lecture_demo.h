#pragma once
// scenes/lecture-demo.json worked out by hand, for the inspection tests: no rotation, a 90°
// diagonal FOV at aspect 4/3, so the sheet at distance 1 spans x in ±0.8 and y in ±0.6
// (m = tan 45° / √(16/9 + 1) = 0.6); plane y = 0, sphere (-10, 60, 0) r 10, light
// (30, 100, -70) of intensity 10000, eye (0, 60, -120). Nothing here calls hexray.

#include <cmath>
#include <cstdint>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace hexray::test::lecture_demo {

inline const glm::dvec3 kEye(0, 60, -120);
inline const glm::dvec3 kSphereCenter(-10, 60, 0);
inline constexpr double kSphereRadius = 10;
inline const glm::dvec3 kLight(30, 100, -70);

// The ray through the centre of pixel (x, y) of a width × height image.
inline glm::dvec3 direction(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height) {
    return glm::normalize(glm::dvec3(-0.8 + 1.6 * (x + 0.5) / width, 0.6 - 1.2 * (y + 0.5) / height, 1.0));
}

inline std::optional<double> planeT(const glm::dvec3& d) {
    return d.y < 0 ? std::optional<double>(-kEye.y / d.y) : std::nullopt;
}

inline std::optional<double> sphereT(const glm::dvec3& d) {
    const glm::dvec3 f = kEye - kSphereCenter;
    const double b = glm::dot(f, d);
    const double disc = b * b - (glm::dot(f, f) - kSphereRadius * kSphereRadius);
    return disc >= 0 ? std::optional<double>(-b - std::sqrt(disc)) : std::nullopt;
}

// Distance from the sphere's centre to the segment p -> light.
inline double segmentClearance(const glm::dvec3& p) {
    const glm::dvec3 s = kLight - p;
    const double u = std::clamp(glm::dot(kSphereCenter - p, s) / glm::dot(s, s), 0.0, 1.0);
    return glm::length(p + u * s - kSphereCenter);
}

// The pixel (of 800 × 600) at the centre of the sphere's shadow on the floor: the centre
// projected from the light onto y = 0 is (-70, 0, 105), seen at (-70, -60, 225) from the eye.
inline constexpr std::uint32_t kShadowX = 244;  // (−70/225 + 0.8) / 1.6 · 800 = 244.4
inline constexpr std::uint32_t kShadowY = 433;  // (0.6 + 60/225) / 1.2 · 600 = 433.3
// A lit floor pixel: the ray (0.001, -0.401, 1) meets the floor at z ≈ 29.6, cell (0, 1), odd.
inline constexpr std::uint32_t kFloorX = 400;
inline constexpr std::uint32_t kFloorY = 500;
// The sphere, near its centre: (−10/120 + 0.8) / 1.6 · 800 = 358.3.
inline constexpr std::uint32_t kSphereX = 358;
inline constexpr std::uint32_t kSphereY = 299;

}  // namespace hexray::test::lecture_demo
