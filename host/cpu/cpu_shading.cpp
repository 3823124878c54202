#include "cpu/cpu_shading.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <variant>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "image/pixel_class.h"
#include "cpu/double_math.h"

namespace hexray::inline cpu {

namespace {

bool isOddInteger(double integral) {
    // fmod is exact, and needs no conversion to an integer type: a cast of a double
    // beyond +-2^63 would be undefined. Doubles that large are all even anyway.
    return std::fmod(integral, 2.0) != 0.0;
}

// A point of a sphere seen from inside, whose surface faces a light outside that sphere: the
// segment to the light runs into the ball and must leave it before the light (convexity), so the
// sphere blocks it, exactly. Decided so rather than by the shadow ray, whose offset (roundoff of
// the world coordinates, shadowRayOffset) can step over a light closer than that to the sphere.
bool isBlockedByOwnSphere(const Geometry& geometry, const Hit& hit, const glm::dvec3& lightPosition) {
    const auto* sphere = std::get_if<Sphere>(&geometry);
    const bool seenFromInside = glm::dot(hit.facingNormal, hit.geometricNormal) < 0.0;
    return sphere && seenFromInside && glm::dot(hit.facingNormal, lightPosition - hit.point) > 0.0 &&
           glm::length(lightPosition - sphere->center) > sphere->radius;
}

}  // namespace

int checkerParity(double u, double v, double size) {
    const double cellU = std::floor(u / size);
    const double cellV = std::floor(v / size);
    return isOddInteger(cellU) == isOddInteger(cellV) ? 0 : 1;
}

Color checkerColor(const CheckerShader& checker, const glm::dvec2& uv) {
    return checkerParity(uv.x, uv.y, checker.size) == 0 ? checker.color1 : checker.color2;
}

glm::dvec2 planeTextureCoordinates(const glm::dvec3& point) {
    return {point.x, point.z};
}

glm::dvec2 sphereTextureCoordinates(const glm::dvec3& outwardNormal) {
    const double longitude = glm::degrees(std::atan2(outwardNormal.x, outwardNormal.z));
    // Rounding can leave |n.y| a hair above 1 at the poles, where asin would give NaN.
    const double latitude = glm::degrees(std::asin(std::clamp(outwardNormal.y, -1.0, 1.0)));
    return {longitude, latitude};
}

glm::dvec2 textureCoordinates(const Geometry& geometry, const Hit& hit, const glm::dvec3& frameOrigin) {
    if (std::holds_alternative<Plane>(geometry)) {
        return planeTextureCoordinates(frameOrigin + hit.point);
    }
    // The outward normal, not the facing one: the pattern belongs to the surface, not the viewer.
    return sphereTextureCoordinates(hit.geometricNormal);
}

double shadowRayOffset(const Geometry& geometry) {
    if (std::holds_alternative<Plane>(geometry)) {
        return 0.0;
    }
    // The reprojected point c + r*normalize(...) is computed from terms as large as |c_i|
    // and r, so its distance from the true surface is bounded by a few units of roundoff
    // of S = max|c_i| + r: ~2 for the normalize, 1 for r*n, 1 for the sum; the shadow ray's
    // own f = o - c and c' = f.f - r^2 add ~2 more. 8 * DBL_EPSILON * S (16 units of
    // roundoff) covers that with room to spare, yet stays ~1e-15 relative: far below
    // anything visible. S, not max|p_i|, because p can sit near 0 on a sphere whose
    // centre is far away; a fixed epsilon would vanish below half an ulp at large |c|.
    // Pushing by >= 16 units of roundoff of |p| also survives the rounding of p + offset*n.
    const Sphere& sphere = std::get<Sphere>(geometry);
    const double coordinateScale = largestAbsComponent(sphere.center) + std::abs(sphere.radius);
    return 8.0 * DBL_EPSILON * coordinateScale;
}

bool isSegmentClear(const Scene& scene, const glm::dvec3& from, const glm::dvec3& to, double shortenBy,
                    const Bvh* bvh) {
    const glm::dvec3 toTarget = to - from;
    const double distance = glm::length(toTarget);
    const double maxDistance = distance - shortenBy;
    if (!(maxDistance > 0.0)) {
        return true;  // the target is within the offset: nothing can lie in between
    }
    // A plane blocks the segment exactly when its ends lie strictly on opposite sides: decided
    // without a division, so a light lying in a plane is never blocked by that plane.
    bool planeBlocks = false;
    forEachPlane(scene, bvh, [&](std::size_t, const Plane& plane) {
        const double fromSide = from.y - plane.height;
        const double toSide = to.y - plane.height;
        planeBlocks = planeBlocks || (fromSide < 0.0 && toSide > 0.0) || (fromSide > 0.0 && toSide < 0.0);
    });
    if (planeBlocks) {
        return false;
    }
    const Ray shadowRay{from, toTarget / distance};
    return !hasSphereHitBefore(shadowRay, scene, maxDistance, bvh);
}

bool isLightVisible(const Scene& scene, const Geometry& geometry, const Hit& hit, const glm::dvec3& lightPosition,
                    const Bvh* bvh) {
    if (isBlockedByOwnSphere(geometry, hit, lightPosition)) {
        return false;
    }
    const double offset = shadowRayOffset(geometry);
    const glm::dvec3 origin = hit.point + offset * hit.facingNormal;
    return isSegmentClear(scene, origin, lightPosition, offset, bvh);
}

LightDecision decideLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const PointLight& light,
                          const Bvh* bvh) {
    const glm::dvec3 toLight = light.position - hit.point;
    const double distanceSquared = glm::dot(toLight, toLight);
    if (distanceSquared == 0.0) {
        return {LightReach::AtPoint, 0.0, 0.0};  // a light on the point itself has no direction; 0 rather than 0/0
    }
    const glm::dvec3 directionToLight = toLight / std::sqrt(distanceSquared);
    const double cosTheta = glm::dot(hit.facingNormal, directionToLight);
    if (cosTheta <= 0.0) {
        // Lit from behind: no light, and no shadow ray to go wrong at the terminator.
        return {LightReach::FacingAway, cosTheta, distanceSquared};
    }
    if (!isLightVisible(scene, geometry, hit, light.position, bvh)) {
        return {LightReach::Shadowed, cosTheta, distanceSquared};
    }
    return {LightReach::Lit, cosTheta, distanceSquared};
}

Color incidentLight(const Scene& scene, const Geometry& geometry, const Hit& hit, const Bvh* bvh,
                    std::uint32_t* litBits, std::vector<LightTerm>* terms) {
    Color total = scene.ambient;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& light = scene.lights[i];
        LightTerm term{decideLight(scene, geometry, hit, light, bvh), Color(0.0)};
        const LightDecision& decision = term.decision;
        if (decision.reach == LightReach::Lit) {
            // Capped at the largest double: a light nearly touching the point would give inf, and a
            // zero albedo channel times inf NaN. A term that large saturates the pixel anyway.
            const double irradiance = std::min(light.intensity * decision.cosTheta / decision.distanceSquared, DBL_MAX);
            term.contribution = glm::min(light.color * irradiance, Color(DBL_MAX));
            total = glm::min(total + term.contribution, Color(DBL_MAX));
            if (litBits) {
                *litBits |= PixelClass::litBit(std::uint32_t(i));
            }
        }
        if (terms) {
            terms->push_back(term);
        }
    }
    return total;
}

ShadedHit shadeHit(const Scene& scene, const Node& node, const Hit& hit, const Bvh* bvh,
                   std::vector<LightTerm>* lightTerms, const glm::dvec3& frameOrigin) {
    const Shader& shader = scene.shaders.at(node.shaderIndex);
    ShadedHit shaded;
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        shaded.albedo = shaded.color = constant->color;
        return shaded;
    }
    if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        shaded.albedo = lambert->color;
    } else {
        const CheckerShader& checker = std::get<CheckerShader>(shader);
        const glm::dvec2 uv = textureCoordinates(node.geometry, hit, frameOrigin);
        shaded.checkerUv = uv;
        shaded.albedo = checkerColor(checker, uv);
        if (checkerParity(uv.x, uv.y, checker.size) == 1) {
            shaded.flags |= PixelClass::kOddCheckerBit;
        }
    }
    shaded.color = shaded.albedo * incidentLight(scene, node.geometry, hit, bvh, &shaded.flags, lightTerms);
    return shaded;
}

}  // namespace hexray::cpu
