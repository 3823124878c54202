#pragma once
// How close each discrete decision of the CPU reference came to going the other way, so that a
// comparison with the shader can tell an honest disagreement (a ray within rounding error of an
// edge) from a bug.
//
// Every margin function here gives a relative margin: the distance of the decision from its
// boundary, divided by the length that roundoff of that decision is proportional to (its
// "scale"), so that a relative perturbation of the shader's inputs and intermediates of size m
// moves it by about m. The shader works in camera-relative coordinates, so every scale is built
// from distances to the camera (|p - eye|, never |p|); the distances to boundaries come from the
// same world-space quantities the CPU intersection and shading use. Each function measures one
// decision; decisionBounds says how small a relative margin must be to count as near-tied.

#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "camera/camera.h"
#include "cpu/cpu_intersect.h"
#include "image/pixel_class.h"
#include "precision/decision_roundoff.h"
#include "scene/scene.h"

namespace hexray::inline cpu {

// How far roundoff can move the unit direction of a camera ray as the shader forms it, in units
// of roundoff: topLeft + right * s.x + down * s.y (`sheetPosition` = s) from float copies of the
// sheet, each component off by up to 8 units of its terms' magnitudes (the copies, s itself, the
// product, two sums), over the target's length; normalizing adds 5 (the dot product, a 2-ulp
// inverse square root, the product). A wide field of view makes it large: the terms then nearly
// cancel at the centre of the image.
double cameraDirectionRoundoff(const PixelSheet& sheet, const glm::dvec2& sheetPosition);

// The relative margins below which one camera ray's decisions are near-tied: twice a bound on
// how far roundoff moves them, (direction + 16) units of roundoff (cameraDirectionRoundoff, and
// 16 for the float copies of the scene and the decision's own chain of operations). Sphere
// checker cells never less than 128 float32 units: they come from the driver's float atan,
// whose accuracy the shader cannot state.
struct DecisionBounds {
    double general;
    double sphereChecker;
};
DecisionBounds decisionBounds(const DecisionRoundoff& roundoff, double directionRoundoff);

// A pixel's margin (CpuRender::margins) is its smallest relative margin in units of that
// decision's bound: below 1 the decision is near-tied, and the pixel ambiguous.
inline constexpr double kAmbiguityMargin = 1.0;

// The smallest of a group of margins (the decisions about one part of a pixel's class).
struct MarginAccumulator {
    double smallest = std::numeric_limits<double>::infinity();  // no decision yet

    // A NaN margin counts as 0: a decision that cannot be measured is not a safe one.
    void add(double margin);

    // As CpuRender::margins stores it: the float at or below `smallest`, so that a margin below
    // kAmbiguityMargin stays below it after rounding; infinity when no decision was made.
    float stored() const;
};

// The decisions made for one ray, by the part of the pixel's classification each decides.
struct RayDecisions {
    MarginAccumulator all;     // every margin, in units of its bound
    PixelAmbiguity ambiguity;  // the parts with a margin below kAmbiguityMargin

    // A margin in units of its bound; `part`: what it leaves undecided when it is near-tied.
    void add(double margin, const PixelAmbiguity& part);
};

// The part of a pixel's class that a decision about light `index` decides: its lit bit, or for
// a light beyond PixelClass::kClassifiedLights, the colour only.
PixelAmbiguity lightPart(std::size_t index);

// ---------------------------------------------------------------- scales

// |c - eye| + r: what the arithmetic of a ray/sphere test is rounded against when the sphere
// is given relative to the camera.
double sphereScale(const Sphere& sphere, const glm::dvec3& eye);

// How far float32 roundoff can move the point a camera ray hit, per unit of relative roundoff:
// |p - eye| for a plane, |c - eye| + r for a sphere, divided by |d.n| in both cases: the hit
// slides along the ray by an amount that grows as the ray grazes the surface (the plane's
// t = h/d.y divides by d.y; the sphere's near root by the half-chord, which is |d.n| r).
// Infinite where the ray is tangent to the surface.
double hitPointScale(const Geometry& geometry, const Hit& hit, const Ray& cameraRay);

// ---------------------------------------------------------------- intersection

// Whether the sphere's surface crosses the ray inside the open range (0, tMax): hit or miss for
// a camera ray (tMax = infinity), shadowed or not for a shadow ray (tMax = distance to the light).
// With f = o - c and l = f - (f.d)d, the quantities of the intersection, float32 can flip it by
// - moving the line across the silhouette: |r - |l||, where that crossing matters, i.e. where
//   the chord overlaps the range (cutting line) or the closest point -f.d lies within the range
//   (missing line; outside it the sphere must reach the range too, so the larger of the two);
// - moving a root t across an end of the range. For a shadow segment that is the end crossing
//   the surface: the end's distance from the sphere, ||o - c| - r| and ||o + tMax d - c| - r|,
//   far less than |t| or |t - tMax| where the ray grazes the sphere there (roundoff moves a root
//   by the surface's move over the cosine between the ray and the normal). For a camera ray,
//   whose eye's side of each sphere every kernel takes from the host's power in double, |t|.
// Each distance is divided by `scale`: |o - eye| + sphereScale for a camera ray, plus the
// light's and the hit point's scales for a shadow ray.
double sphereCrossingMargin(const Ray& ray, const Sphere& sphere, double tMax, double scale);

// sphereCrossingMargin in its two parts: the line crossing the silhouette, and a root crossing
// an end of the range (for a camera ray: its start, where the eye lies within roundoff of the
// sphere, which then decides which of the sphere's surfaces the ray sees). Infinity where none.
struct SphereCrossingMargins {
    double line;
    double ends;
};
SphereCrossingMargins sphereCrossingMargins(const Ray& ray, const Sphere& sphere, double tMax, double scale);

// A shadow ray from a point of a sphere seen from inside (the sphere holds the camera) toward
// a light: unlike a convex surface seen from outside, the sphere blocks its own points, when
// the light lies outside it and the ray leaves the sphere before reaching the light. The
// distance between that exit and the light (at tMax), over `scale`.
double ownSphereShadowMargin(const Ray& shadowRay, const Sphere& sphere, double tMax, double scale);

// Which side of a sphere seen from inside a light lies on: the shader takes a light outside the
// sphere that holds the eye as blocked by it (sphereHidesLight), and so does the reference at the
// sphere's points (isLightVisible). ||L - c| - r|, the light's distance from the sphere, over `scale`.
double lightSideMargin(const glm::dvec3& light, const Sphere& sphere, double scale);

// A camera ray against the plane y = h: whether it hits is the sign of d.y (a plane through the
// camera, h - eye.y == 0, is always missed: no decision, infinity). The shader's unit direction
// carries an absolute error of a few units of roundoff, so the margin is |d.y|.
double cameraRayPlaneMargin(double directionY, double heightAboveCamera);

// A shadow segment against the plane y = h: it is blocked when its ends lie strictly on opposite
// sides, so float32 flips it by moving either end across the plane. The ends' heights above
// the plane (o.y - h, L.y - h) over `scale` (|o - eye| + |L - eye| + |h - eye.y|).
double planeSegmentMargin(double originHeight, double targetHeight, double scale);

// Which node is nearest: float32 swaps two hits when their distances' roundoff exceeds the gap.
// (t2 - t1) / scale, with t1 the nearest hit, t2 another node's hit and scale the sum of the
// two hits' hitPointScale.
double nearestNodeMargin(double nearestT, double otherT, double scale);

// ---------------------------------------------------------------- shading

// How far float32 roundoff can move a plane hit's texture coordinates (x, z), per unit of
// relative roundoff, each on its own: the hit eye + (h / d.y) d moves with the direction by
// t = |p - eye| along its own axis and by |p_u - eye_u| / |d.y| through d.y. (So a line of cells
// running away from the camera is sharper than one across the view.) Infinite for a ray
// parallel to the plane.
glm::dvec2 planeTextureScales(const Hit& hit, const Ray& cameraRay);

// Which checker cell a plane hit is in: floor(u/size) and floor(v/size) flip when roundoff moves
// (u, v) across a multiple of size. For each axis the distance (in length) to the nearest such
// line, over that axis's scale (planeTextureScales) plus size (the shader's cell coordinates
// carry roundoff of both); the smaller of the two.
double planeCheckerMargin(const glm::dvec2& uv, double size, const glm::dvec2& uvScales);

// Which checker cell a sphere hit is in, for (longitude, latitude) = (degrees(atan2(n.x, n.z)),
// degrees(asin(n.y))) of the outward normal n. Measured in the space of n, where roundoff
// acts: a latitude edge is the circle n.y = sin(edge), at distance |n.y - sin(edge)| (so asin's
// growing sensitivity toward the poles is included); a meridian, including atan2's cut at
// +-180 (always an edge of the computation), is a half-plane through the polar axis, at
// distance rho * sin(angle), rho = |(n.x, n.z)|, so all meridians meet at the poles. Divided by
// `normalRoundoff`, the normal's roundoff per unit (hitPointScale / r).
double sphereCheckerMargin(const glm::dvec3& outwardNormal, double size, double normalRoundoff);

// Whether the surface faces the light, the sign of cos = n . (L - p) / |L - p|: |cos| over the
// roundoff of n (0 for a plane, whose normal is exact; hitPointScale / r for a sphere) plus that
// of the direction to the light ((hitPointScale + |L - eye|) / |L - p|). The same form tells which
// side of a sphere faces the camera ray (cos = n . d, the ray's direction erring by about a unit).
double facingMargin(double cosTheta, double normalRoundoff, double directionRoundoff);

// Not a decision but the colour a lit light gives: its term I cos / r^2 carries roundoff of r^2 and
// of the direction to the light (directionRoundoff each, r^2 twice) and of cos (the normal's too),
// relative to I / r^2, a few units each (kLightTermUnits) of `unitRoundoff`. Where that exceeds
// kLightTermTolerance (an 8-bit level of a full-bright linear channel, the finest a level is
// relative to its value), two correct renderers may differ by a level on this light alone: a light
// close to a point whose position the arithmetic rounds on a far larger scale (a huge sphere's
// surface beside a light a hair above it). The margin in units of that tolerance.
inline constexpr double kLightTermTolerance = LIGHT_TERM_TOLERANCE;  // unit_roundoff.h, with the shader
inline constexpr double kLightTermUnits = LIGHT_TERM_UNITS;
double lightTermMargin(double normalRoundoff, double directionRoundoff, double unitRoundoff);

}  // namespace hexray::cpu
