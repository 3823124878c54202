#pragma once
// The accuracy oracle: what the scene model (docs/scene-format.md, "The model") says one ray sees, computed
// exactly (exact.h) from the ray's origin and direction taken as the exact binary numbers given,
// with the conditioning of every answer. It shares no code with either renderer: it reads the
// scene model and nothing else of hexray.
//
// Conditioning. Every discrete decision has a margin, its distance from flipping in its own unit
// (a length, or cos theta for facing a light); every value is a number. Four moves of the input
// each move a margin or value by some amount: the ray's direction by one unit of roundoff u of the
// precision under test along each axis in turn, and the scene as a renderer at that precision
// holds it relative to the ray's origin (every centre, plane height and light's offset from the
// origin, and every radius, rounded to the precision: no move where they are representable). The
// root sum of squares of the four moves is the sensitivity. A decision's conditioning is
// |margin| / sensitivity: how many such units it is from flipping. The origin is exact as given.

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace hexray::oracle {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct LightTruth {
    bool atPoint = false;  // the light lies on the point: no direction, no term
    bool facing = false;   // cos theta > 0 (with the normal facing the ray)
    bool blocked = false;  // some surface crosses the open segment to the light (asked when facing)
    double cosTheta = 0;
    double distanceSquared = 0;
    double facingMargin = 0;          // cos theta
    double blockMargin = kUnbounded;  // length to the nearest boundary of any node's blocking decision
};

struct RayTruth {
    std::optional<std::size_t> node;  // the nearest hit (earlier node on an exact tie); none: background
    std::vector<double> hitMargins;   // per node, > 0 for a hit, < 0 for a miss (length)
    double nearestGap = kUnbounded;   // the second-nearest hit's t minus the nearest's
    double t = 0;                     // distance along the unit direction
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};             // facing the ray
    double scale = 0;                   // the magnitude the hit's arithmetic works at (see distanceScale)
    double radius = 0;                  // of the hit sphere; 0 for a plane
    std::optional<bool> oddChecker;     // checker-shaded hits
    double checkerMargin = kUnbounded;  // plane: length to the nearest cell edge; sphere: degrees
    std::vector<LightTruth> lights;
};

// The exact answer for the ray from `origin` along `direction` (normalised exactly).
RayTruth trace(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction);

// The answer with its conditioning at unit roundoff `u`. Decisions' conditionings are in units of
// roundoff (kUnbounded where no perturbation moves the margin); values' sensitivities are in the
// values' units. A decision downstream of the hit (checker, lights, values) whose perturbed rays
// hit another node gets conditioning 0.
struct Judged {
    RayTruth truth;
    double unitRoundoff = 0;
    double nodeConditioning = kUnbounded;  // min over every node's hit or miss and the nearest gap
    double checkerConditioning = kUnbounded;
    std::vector<double> lightConditioning;  // facing, and (when facing) every node's blocking
    double tSensitivity = 0;
    double normalSensitivity = 0;  // largest component
    std::vector<double> cosSensitivity;
    std::vector<double> distanceSquaredSensitivity;
};

Judged judge(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction, double unitRoundoff);

}  // namespace hexray::oracle
