#pragma once
// How close each discrete decision of the CPU reference came to going the other way, so that a
// comparison with the float32 shader can tell an honest disagreement (a ray within rounding
// error of an edge) from a bug.
//
// Every margin here is dimensionless: the distance of the decision from its boundary, divided
// by the length that float32 roundoff of that decision is proportional to (its "scale").
// Roughly, a margin m survives any perturbation of the shader's inputs and intermediates of
// relative size below m; kAmbiguityMargin (cpu_renderer.h) asks for 128 float32 units.
// The shader works in camera-relative coordinates, so every scale is built from distances to
// the camera (|p - eye|, never |p|); the distances to boundaries come from the same world-space
// quantities the CPU intersection and shading use. Each function measures one decision.

#include <limits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cpu/cpu_intersect.h"
#include "scene/scene.h"

namespace hexray {

// The smallest margin over the decisions made for one pixel.
struct MarginAccumulator {
    double smallest = std::numeric_limits<double>::infinity();  // no decision yet

    // A NaN margin counts as 0: a decision that cannot be measured is not a safe one.
    void add(double margin);

    // As CpuRender::margins stores it: the float at or below `smallest`, so that a margin below
    // kAmbiguityMargin stays below it after rounding; infinity when no decision was made.
    float stored() const;
};

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
//   (missing line; outside it the gap to the range must close too, so the larger of the two);
// - moving a root t across an end of the range: |t| and |t - tMax|.
// Each distance is divided by `scale`: |o - eye| + sphereScale for a camera ray, plus the
// light's and the hit point's scales for a shadow ray.
double sphereCrossingMargin(const Ray& ray, const Sphere& sphere, double tMax, double scale);

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

// Which checker cell a plane hit is in: floor(u/size) and floor(v/size) flip when roundoff moves
// (u, v) across a multiple of size. The distance (in length) to the nearest such line, over
// the hit's scale plus size (the shader's cell coordinates carry roundoff of both).
double planeCheckerMargin(const glm::dvec2& uv, double size, double hitScale);

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
// of the direction to the light ((hitPointScale + |L - eye|) / |L - p|).
double facingMargin(double cosTheta, double normalRoundoff, double directionRoundoff);

}  // namespace hexray
