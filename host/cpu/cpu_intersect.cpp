#include "cpu/cpu_intersect.h"

#include <cmath>
#include <utility>
#include <variant>

#include <glm/geometric.hpp>

namespace hexray {

std::optional<Hit> intersectPlane(const Ray& ray, const Plane& plane) {
    // A parallel ray (d.y = +0 or -0) never meets the plane; dividing would give +-inf or NaN.
    if (ray.direction.y == 0.0) {
        return std::nullopt;
    }
    const double t = (plane.height - ray.origin.y) / ray.direction.y;
    // t <= 0: the plane is behind the ray, or the ray starts on it.
    // Non-finite: a denormal d.y overflowed the division; no real hit is that far.
    if (!std::isfinite(t) || t <= 0.0) {
        return std::nullopt;
    }

    Hit hit;
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    // Snap onto the plane: a shadow ray from here can then never hit this plane again
    // (its t would be exactly 0), so planes need no shadow-ray offset.
    hit.point.y = plane.height;
    hit.geometricNormal = glm::dvec3(0.0, 1.0, 0.0);
    // A ray going down came from above, so the visible side faces up.
    hit.facingNormal = glm::dvec3(0.0, ray.direction.y < 0.0 ? 1.0 : -1.0, 0.0);
    return hit;
}

std::optional<Hit> intersectSphere(const Ray& ray, const Sphere& sphere) {
    const glm::dvec3& d = ray.direction;
    const double r = sphere.radius;

    const glm::dvec3 f = ray.origin - sphere.center;
    const double halfB = glm::dot(f, d);
    // From the centre to the ray's closest point. Subtracting as vectors keeps |l| accurate
    // when the sphere is small and far away; r^2 - (|f|^2 - b'^2) would cancel catastrophically.
    const glm::dvec3 l = f - halfB * d;
    const double lengthL = glm::length(l);
    // (r - |l|)(r + |l|) is a little more precise than r^2 - |l|^2.
    const double discriminant = (r - lengthL) * (r + lengthL);
    if (discriminant < 0.0) {
        return std::nullopt;
    }

    // Both terms of q have the same sign, so q is never a difference of near-equal numbers;
    // the other root comes from the product of roots (c'/a with a = 1).
    const double q = -halfB - std::copysign(std::sqrt(discriminant), halfB);
    if (q == 0.0) {
        // Only when b' = 0 and the discriminant is 0: a ray starting on the sphere, tangent
        // to it. Both roots are 0, and 0 is not a hit.
        return std::nullopt;
    }
    const double c = glm::dot(f, f) - r * r;
    double tNear = c / q;
    double tFar = q;
    if (tNear > tFar) {
        std::swap(tNear, tFar);
    }

    double t = 0.0;
    if (tNear > 0.0) {
        t = tNear;
    } else if (tFar > 0.0) {
        t = tFar;  // the ray starts inside the sphere
    } else {
        return std::nullopt;  // the sphere is behind the ray
    }
    if (!std::isfinite(t)) {
        return std::nullopt;
    }

    Hit hit;
    hit.t = t;
    // Reproject onto the sphere: o + t*d carries the rounding error of t times |d|, which
    // would leave the point off the surface (acne); the direction from the centre is accurate.
    const glm::dvec3 outward = glm::normalize(ray.origin + t * d - sphere.center);
    hit.point = sphere.center + r * outward;
    hit.geometricNormal = (hit.point - sphere.center) / r;
    const bool rayLeavesThroughSurface = glm::dot(hit.geometricNormal, d) > 0.0;
    hit.facingNormal = rayLeavesThroughSurface ? -hit.geometricNormal : hit.geometricNormal;
    return hit;
}

std::optional<Hit> intersectGeometry(const Ray& ray, const Geometry& geometry) {
    if (const auto* plane = std::get_if<Plane>(&geometry)) {
        return intersectPlane(ray, *plane);
    }
    return intersectSphere(ray, std::get<Sphere>(geometry));
}

std::optional<SceneHit> findNearestHit(const Ray& ray, const Scene& scene) {
    std::optional<SceneHit> nearest;
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        const std::optional<Hit> hit = intersectGeometry(ray, scene.nodes[index].geometry);
        // Strictly smaller replaces, so on an exact tie the earlier node keeps the pixel.
        if (hit && (!nearest || hit->t < nearest->hit.t)) {
            nearest = SceneHit{*hit, index};
        }
    }
    return nearest;
}

}  // namespace hexray
