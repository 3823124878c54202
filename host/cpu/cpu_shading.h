#pragma once
// Shading for the CPU reference renderer: checker texture, Lambert light with shadow rays,
// constant colour. Double precision, written independently of the shader.

#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cpu/cpu_intersect.h"
#include "scene/scene.h"

namespace hexray {

// 0 when floor(u/size) + floor(v/size) is even (color1's cells), 1 when odd (color2's).
// Correct through negative coordinates and for |u/size| beyond the range of any integer type.
int checkerParity(double u, double v, double size);

Color checkerColor(const CheckerShader& checker, const glm::dvec2& uv);

// Plane: (u, v) = (x, z) of the hit point.
glm::dvec2 planeTextureCoordinates(const glm::dvec3& point);

// Sphere: (longitude, latitude) in degrees of the outward unit normal:
// (degrees(atan2(n.x, n.z)), degrees(asin(n.y))).
glm::dvec2 sphereTextureCoordinates(const glm::dvec3& outwardNormal);

glm::dvec2 textureCoordinates(const Geometry& geometry, const Hit& hit);

// How far a shadow ray's origin is pushed off the surface along the facing normal:
// 0 for planes (the snapped hit point cannot re-hit its plane), an error bound of a few
// ulp of the coordinates' magnitude for spheres.
double shadowRayOffset(const Geometry& geometry);

// True when no plane has `from` and `to` strictly on opposite sides, and no sphere has a hit
// with 0 < t < |to - from| - shortenBy on the ray from `from` toward `to`. Shortening keeps a
// light lying exactly on a sphere from being blocked by it; the plane rule needs none.
// Here and below, `bvh` (when given, built from `scene`) only speeds up the shadow rays.
bool isSegmentClear(const Scene& scene, const glm::dvec3& from, const glm::dvec3& to, double shortenBy,
                    const Bvh* bvh = nullptr);

// Whether the light at `lightPosition` can see the hit point (the shadow ray, offset as above).
bool isLightVisible(const Scene& scene, const Geometry& geometry, const Hit& hit,
                    const glm::dvec3& lightPosition, const Bvh* bvh = nullptr);

// How a light reaches a hit point that it lights.
struct ReachingLight {
    double cosTheta = 0.0;         // facing normal . direction to the light, > 0
    double distanceSquared = 0.0;  // from the hit point to the light, > 0
};

// Why a light does or does not reach a hit point, with the terms that decided it (the
// instrumented form of reachingLight, for `hexray pixel`).
enum class LightReach { Lit, AtPoint, FacingAway, Shadowed };
struct LightDecision {
    LightReach reach = LightReach::AtPoint;
    double cosTheta = 0.0;         // 0 when AtPoint
    double distanceSquared = 0.0;
};
LightDecision decideLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const PointLight& light,
                          const Bvh* bvh = nullptr);

// The light's cos and squared distance when it contributes to the hit; nothing when it does not:
// it lies on the point itself, the surface faces away from it (cos <= 0), or it is shadowed.
std::optional<ReachingLight> reachingLight(const Scene& scene, const Geometry& geometry, const Hit& hit,
                                           const PointLight& light, const Bvh* bvh = nullptr);

// ambient + sum over visible lights of lightColor * intensity * max(0, cos) / r^2.
// No pi factor: intensity 10000 at distance 100 at normal incidence gives 1.
Color incidentLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const Bvh* bvh = nullptr);

// albedo (component-wise) times the incident light.
Color shadeLambert(const Scene& scene, const Geometry& geometry, const Hit& hit, const Color& albedo,
                   const Bvh* bvh = nullptr);

// The colour the node's shader gives this hit.
Color shadeHit(const Scene& scene, const Node& node, const Hit& hit, const Bvh* bvh = nullptr);

}  // namespace hexray
