#pragma once
// One renderer's answer for a ray against the oracle's (oracle.h): every decision the oracle calls
// well conditioned must be right, and every well-conditioned value within a stated bound.
//
// - A decision is well conditioned when it is at least kWellConditioned units of roundoff of the
//   direction from flipping. Decisions: which node the ray shows (every node's hit or miss and
//   which is nearest), the checker cell's parity, and each light's status (lit, facing away,
//   shadowed). Those after the hit are judged only where the node is well conditioned and right.
// - The distance must be within kDistanceUlps ulps of the hit's scale S (RayTruth::scale) where
//   one unit of roundoff of the direction moves it by at most kValueSensitivity such ulps.
// - Normals, cos theta and r^2 likewise, in their own units: u * max(1, S / r) for a sphere's
//   normal (a hit point known to an ulp of S gives its direction to that), u for a plane's;
//   cos theta the normal's unit plus u * P / |L - p|; r^2 relative, 2 u * P / |L - p| plus 4 u, where
//   P, the magnitude the hit point is held at, is max(S, t), and for a renderer working in world
//   coordinates (the CPU reference) also |o| and |p|. Bounds are kValueBound of these units.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/oracle.h"

namespace hexray::oracle {

inline constexpr double kWellConditioned = 64.0;
inline constexpr double kDistanceUlps = 8.0;
inline constexpr double kValueSensitivity = 2.0;  // in the value's unit, per unit of roundoff of the direction
inline constexpr double kValueBound = 8.0;

enum class LightStatus { Lit, FacingAway, Shadowed, AtPoint };

// What a renderer reports for one ray, in world units.
struct RendererRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0};      // as the renderer used it: the oracle judges this ray
    bool worldCoordinates = false;  // positions held in world coordinates, not relative to the eye
    std::optional<std::size_t> node;
    double t = 0;
    glm::dvec3 normal{0.0};  // facing the ray
    bool oddChecker = false;
    struct Light {
        LightStatus status = LightStatus::AtPoint;
        double cosTheta = 0;
        double distanceSquared = 0;
    };
    std::vector<Light> lights;
};

// Counts over many rays, and what went wrong.
struct Tally {
    std::uint64_t rays = 0;
    std::uint64_t decisions = 0;  // well conditioned, and judged
    std::uint64_t rightDecisions = 0;
    std::uint64_t distances = 0;  // well conditioned, and judged
    double maxDistanceUlps = 0;
    std::uint64_t values = 0;  // normals, cos theta, r^2
    double maxValueUnits = 0;  // the largest error over all values, in each value's unit
    std::vector<std::string> failures;

    void add(const Tally& other);
};

// Checks `rendered` against the oracle's judgement of the ray it followed at unit roundoff `u`
// (the caller judges rendered.origin and rendered.direction), adding to `tally`; failures are
// labelled with `label`.
void checkRay(const Judged& judged, const RendererRay& rendered, const std::string& label, Tally& tally);

// ulp of x at the precision whose unit roundoff is u: 2u * 2^floor(log2 |x|).
double ulpAt(double x, double unitRoundoff);

}  // namespace hexray::oracle
