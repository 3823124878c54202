#include "cpu/cpu_margins.h"
#include "unit_roundoff.h"
#include "cpu/double_math.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace hexray::inline cpu {

namespace {

// Distance from x to the nearest multiple of size (in x's units).
double distanceToMultiple(double x, double size) {
    const double cells = x / size;
    return std::abs(cells - std::nearbyint(cells)) * size;
}

// Distance in n-space from the outward normal to the nearest latitude edge that can be crossed.
double latitudeEdgeDistance(const glm::dvec3& n, double size) {
    const double latitude = glm::degrees(std::asin(std::clamp(n.y, -1.0, 1.0)));
    double nearest = kInfinity;
    for (const double edge : {std::floor(latitude / size) * size, std::ceil(latitude / size) * size}) {
        // A multiple of size beyond a pole is no edge: no latitude reaches it. (sin is symmetric
        // about 90 degrees, so it would otherwise look as near as one on this side.)
        if (std::abs(edge) <= 90.0) {
            nearest = std::min(nearest, std::abs(n.y - std::sin(glm::radians(edge))));
        }
    }
    return nearest;
}

// Distance in n-space from the outward normal to the nearest meridian edge, atan2's cut included.
double longitudeEdgeDistance(const glm::dvec3& n, double size) {
    const double longitude = glm::degrees(std::atan2(n.x, n.z));
    double nearestDegrees = 180.0 - std::abs(longitude);  // the cut at +-180
    for (const double edge : {std::floor(longitude / size) * size, std::ceil(longitude / size) * size}) {
        if (std::abs(edge) <= 180.0) {
            nearestDegrees = std::min(nearestDegrees, std::abs(longitude - edge));
        }
    }
    // A meridian is a half-plane ending on the polar axis: beyond a right angle the nearest
    // point of it is on the axis, at distance rho.
    const double rho = std::hypot(n.x, n.z);
    return rho * std::sin(glm::radians(std::min(nearestDegrees, 90.0)));
}

}  // namespace

void MarginAccumulator::add(double margin) {
    if (std::isnan(margin)) {
        margin = 0.0;
    }
    smallest = std::min(smallest, margin);
}

float MarginAccumulator::stored() const {
    float rounded = static_cast<float>(smallest);
    if (static_cast<double>(rounded) > smallest) {
        rounded = std::nextafter(rounded, 0.0f);  // also brings an overflow to infinity back to FLT_MAX
    }
    return rounded;
}

double cameraDirectionRoundoff(const PixelSheet& sheet, const glm::dvec2& sheetPosition) {
    const glm::dvec3 target = sheet.topLeft + sheet.right * sheetPosition.x + sheet.down * sheetPosition.y;
    const glm::dvec3 terms = glm::abs(sheet.topLeft) + glm::abs(sheet.right) * std::abs(sheetPosition.x) +
                             glm::abs(sheet.down) * std::abs(sheetPosition.y);
    return cameraDirectionUnits(std::max({terms.x, terms.y, terms.z}), glm::length(target));
}

DecisionBounds decisionBounds(const DecisionRoundoff& roundoff, double directionRoundoff) {
    constexpr double kFloat32AtanBound = 128.0 * FLOAT32_UNIT_ROUNDOFF;
    const double units = nearTieUnits(directionRoundoff);
    return {units * roundoff.general, std::max(units * roundoff.sphereChecker, kFloat32AtanBound)};
}

void RayDecisions::add(double margin, const PixelAmbiguity& part) {
    all.add(margin);
    if (!(margin >= kAmbiguityMargin)) {  // NaN too
        ambiguity |= part;
    }
}

PixelAmbiguity lightPart(std::size_t index) {
    if (index < PixelClass::kClassifiedLights) {
        return {false, PixelClass::litBit(std::uint32_t(index)), false};
    }
    return {false, 0, true};
}

double sphereScale(const Sphere& sphere, const glm::dvec3& eye) {
    return glm::length(sphere.center - eye) + std::abs(sphere.radius);
}

double hitPointScale(const Geometry& geometry, const Hit& hit, const Ray& cameraRay) {
    const double grazing = std::abs(glm::dot(cameraRay.direction, hit.geometricNormal));
    const double along = std::holds_alternative<Plane>(geometry)
                             ? glm::length(hit.point - cameraRay.origin)
                             : sphereScale(std::get<Sphere>(geometry), cameraRay.origin);
    return grazing > 0.0 ? along / grazing : kInfinity;
}

double sphereCrossingMargin(const Ray& ray, const Sphere& sphere, double tMax, double scale) {
    const SphereCrossingMargins margins = sphereCrossingMargins(ray, sphere, tMax, scale);
    return std::min(margins.line, margins.ends);
}

SphereCrossingMargins sphereCrossingMargins(const Ray& ray, const Sphere& sphere, double tMax, double scale) {
    const glm::dvec3& d = ray.direction;
    const double r = sphere.radius;
    const glm::dvec3 f = ray.origin - sphere.center;
    const double closestT = -glm::dot(f, d);
    const double lengthL = glm::length(f + closestT * d);
    const double clearance = std::abs(r - lengthL);
    // A root crosses an end of a shadow segment exactly when that end crosses the surface: the
    // kernel rounds the light, the surface point and the sphere, which moves the surface against an
    // end by about the scale, and a root by that over the cosine between the ray and the normal.
    // So an end's distance from the sphere, which a grazing ray's root far exceeds (a light a hair
    // inside a blocker, a shadow ray starting a hair outside one). A camera ray starts at the eye,
    // whose side of each sphere every kernel takes from the host's power in double: there the
    // root's own distance from t = 0.
    const bool segment = std::isfinite(tMax);
    const auto endDistance = [&](double t) { return std::abs(glm::length(f + t * d) - r); };

    if (lengthL > r) {
        // The line misses. Float32 makes it touch the range only if it both reaches the sphere and
        // touches it at a point of the range: outside the range, the nearer end must reach it too.
        const bool closestInRange = closestT >= 0.0 && closestT <= tMax;
        const double outside = closestInRange ? 0.0 : segment ? endDistance(closestT < 0.0 ? 0.0 : tMax) : -closestT;
        return {std::max(clearance, outside) / scale, kInfinity};
    }
    const double halfChord = std::sqrt((r - lengthL) * (r + lengthL));
    double nearest = kInfinity;
    if (segment) {
        nearest = std::min(endDistance(0.0), endDistance(tMax));
    } else {
        for (const double root : {closestT - halfChord, closestT + halfChord}) {
            nearest = std::min(nearest, std::abs(root));  // crossing the start of the range
        }
    }
    const bool chordMeetsRange = closestT + halfChord > 0.0 && closestT - halfChord < tMax;
    // The chord shrinking to nothing matters only where it meets the range.
    return {chordMeetsRange ? clearance / scale : kInfinity, nearest / scale};
}

double ownSphereShadowMargin(const Ray& shadowRay, const Sphere& sphere, double tMax, double scale) {
    const glm::dvec3 f = shadowRay.origin - sphere.center;
    const double closestT = -glm::dot(f, shadowRay.direction);
    const double lengthL = glm::length(f + closestT * shadowRay.direction);
    const double r = sphere.radius;
    // The origin lies on the sphere, so the line cuts it; rounding may put it a hair outside.
    const double exit = closestT + std::sqrt(std::max(0.0, (r - lengthL) * (r + lengthL)));
    return std::abs(exit - tMax) / scale;
}

double lightSideMargin(const glm::dvec3& light, const Sphere& sphere, double scale) {
    return std::abs(glm::length(light - sphere.center) - sphere.radius) / scale;
}

double cameraRayPlaneMargin(double directionY, double heightAboveCamera) {
    if (heightAboveCamera == 0.0) {
        return kInfinity;
    }
    return std::abs(directionY);
}

double planeSegmentMargin(double originHeight, double targetHeight, double scale) {
    return std::min(std::abs(originHeight), std::abs(targetHeight)) / scale;
}

double nearestNodeMargin(double nearestT, double otherT, double scale) {
    return (otherT - nearestT) / scale;
}

glm::dvec2 planeTextureScales(const Hit& hit, const Ray& cameraRay) {
    const double grazing = std::abs(cameraRay.direction.y);
    if (!(grazing > 0.0)) {
        return glm::dvec2(kInfinity);
    }
    const glm::dvec3 offset = hit.point - cameraRay.origin;
    const double t = glm::length(offset);
    return {t + std::abs(offset.x) / grazing, t + std::abs(offset.z) / grazing};
}

double planeCheckerMargin(const glm::dvec2& uv, double size, const glm::dvec2& uvScales) {
    return std::min(distanceToMultiple(uv.x, size) / (uvScales.x + size),
                    distanceToMultiple(uv.y, size) / (uvScales.y + size));
}

double sphereCheckerMargin(const glm::dvec3& outwardNormal, double size, double normalRoundoff) {
    const double edgeDistance =
        std::min(latitudeEdgeDistance(outwardNormal, size), longitudeEdgeDistance(outwardNormal, size));
    return edgeDistance / normalRoundoff;
}

double lightTermMargin(double normalRoundoff, double directionRoundoff, double unitRoundoff) {
    return kLightTermTolerance / ((3.0 * directionRoundoff + normalRoundoff) * kLightTermUnits * unitRoundoff);
}

double facingMargin(double cosTheta, double normalRoundoff, double directionRoundoff) {
    return std::abs(cosTheta) / (normalRoundoff + directionRoundoff);
}

}  // namespace hexray::cpu
