#pragma once
// Shading for the CPU reference renderer: checker texture, Lambert light with shadow rays,
// constant colour. Double precision, written independently of the shader.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cpu/cpu_intersect.h"
#include "scene/scene.h"

namespace hexray::inline cpu {

// 0 when floor(u/size) + floor(v/size) is even (color1's cells), 1 when odd (color2's).
// Correct through negative coordinates and for |u/size| beyond the range of any integer type.
int checkerParity(double u, double v, double size);

Color checkerColor(const CheckerShader& checker, const glm::dvec2& uv);

// Plane: (u, v) = (x, z) of the hit point.
glm::dvec2 planeTextureCoordinates(const glm::dvec3& point);

// Sphere: (longitude, latitude) in degrees of the outward unit normal:
// (degrees(atan2(n.x, n.z)), degrees(asin(n.y))).
glm::dvec2 sphereTextureCoordinates(const glm::dvec3& outwardNormal);

// `frameOrigin`: the world position of the coordinates' origin (EyeFrameScene::eye), which a plane's
// cells, fixed in the world, add back.
glm::dvec2 textureCoordinates(const Geometry& geometry, const Hit& hit,
                              const glm::dvec3& frameOrigin = glm::dvec3(0.0));

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
// A point of a sphere seen from inside that faces a light outside the sphere never can: decided
// exactly, without the shadow ray.
bool isLightVisible(const Scene& scene, const Geometry& geometry, const Hit& hit, const glm::dvec3& lightPosition,
                    const Bvh* bvh = nullptr);

// Why a light does or does not reach a hit point, with the terms that decided it.
enum class LightReach { Lit, AtPoint, FacingAway, Shadowed };
struct LightDecision {
    LightReach reach = LightReach::AtPoint;
    double cosTheta = 0.0;  // 0 when AtPoint
    double distanceSquared = 0.0;
};
// Lit unless the light lies on the point itself, the surface faces away from it (cos <= 0),
// or it is shadowed (the shadow ray, offset as above).
LightDecision decideLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const PointLight& light,
                          const Bvh* bvh = nullptr);

// One light's part in the light a hit receives.
struct LightTerm {
    LightDecision decision;
    Color contribution{0.0};  // colour × intensity × cos θ / r² when lit, else 0
};

// ambient + sum over the lights that reach the hit of colour * intensity * cos / r^2.
// No pi factor: intensity 10000 at distance 100 at normal incidence gives 1. `litBits` (when
// given) receives PixelClass::litBit(i) for each light i that contributes, `terms` (when
// given) every light's term.
Color incidentLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const Bvh* bvh = nullptr,
                    std::uint32_t* litBits = nullptr, std::vector<LightTerm>* terms = nullptr);

// A hit's colour and what decided it: the pixel classification's flags (the odd checker cell,
// a bit per light that contributes) come from the very decisions that made the colour.
struct ShadedHit {
    Color color{0.0};
    Color albedo{0.0};                    // the shader's colour at the hit
    std::optional<glm::dvec2> checkerUv;  // texture coordinates, checker shaders only
    std::uint32_t flags = 0;              // PixelClass flags
};
// The colour the node's shader gives this hit. `lightTerms` (when given) receives every light's
// term for a lit shader; a constant shader evaluates no light. `frameOrigin`: as for
// textureCoordinates.
ShadedHit shadeHit(const Scene& scene, const Node& node, const Hit& hit, const Bvh* bvh = nullptr,
                   std::vector<LightTerm>* lightTerms = nullptr, const glm::dvec3& frameOrigin = glm::dvec3(0.0));

}  // namespace hexray::cpu
