#include "cpu/cpu_intersect.h"
#include "cpu/double_math.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

namespace hexray::inline cpu {

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

namespace {

// |f|^2 - r^2 with about one rounding: each square split exactly into its rounded value and error
// (fma), the eight parts summed with Neumaier's compensation. dot(f, f) - r*r would err by
// eps*(|f|^2 + r^2), which swamps the small power of an origin close to a large sphere.
double powerOfPoint(const glm::dvec3& f, double r) {
    const double squares[4] = {f.x * f.x, f.y * f.y, f.z * f.z, -(r * r)};
    const double errors[4] = {std::fma(f.x, f.x, -squares[0]), std::fma(f.y, f.y, -squares[1]),
                              std::fma(f.z, f.z, -squares[2]), -std::fma(r, r, squares[3])};
    double sum = 0.0;
    double compensation = 0.0;
    for (const double* part : {squares, errors}) {
        for (int i = 0; i < 4; ++i) {
            const double next = sum + part[i];
            compensation += std::abs(sum) >= std::abs(part[i]) ? (sum - next) + part[i] : (part[i] - next) + sum;
            sum = next;
        }
    }
    return sum + compensation;
}

// r^2 - |l|^2 = b'^2 - c', the quarter discriminant, in whichever of its two forms has the smaller
// first-order rounding error bound. (r - |l|)(r + |l|) errs by about 6 eps r (|b'| + r): small for a
// small or distant sphere, where b'^2 and c' are both near |f|^2 and cancel. b'^2 - c' errs by
// about 6 eps |b'||f| + 2 eps |c'| (c' from powerOfPoint): it wins for a ray starting on or near the
// sphere and for a large sphere seen from close by, where |l| is within rounding of r.
double quarterDiscriminant(double halfB, double lengthL, double lengthF, double power, double r) {
    const double fromLine = (r - lengthL) * (r + lengthL);
    const double fromPower = halfB * halfB - power;
    const double lineBound = 6.0 * r * (std::abs(halfB) + r);
    const double powerBound = 6.0 * std::abs(halfB) * lengthF + 2.0 * std::abs(power);
    return powerBound < lineBound ? fromPower : fromLine;
}

}  // namespace

std::optional<Hit> intersectSphere(const Ray& ray, const Sphere& sphere) {
    const glm::dvec3& d = ray.direction;
    const double r = sphere.radius;

    const glm::dvec3 f = ray.origin - sphere.center;
    const double halfB = glm::dot(f, d);
    // From the centre to the ray's closest point. Subtracting as vectors keeps |l| accurate
    // when the sphere is small and far away; r^2 - (|f|^2 - b'^2) would cancel catastrophically.
    const glm::dvec3 l = f - halfB * d;
    const double power = powerOfPoint(f, r);  // c', the origin's power: > 0 outside the sphere
    const double discriminant = quarterDiscriminant(halfB, glm::length(l), glm::length(f), power, r);
    if (discriminant < 0.0) {
        return std::nullopt;
    }

    // Both terms of q have the same sign, so q is never a difference of near-equal numbers;
    // the other root comes from the product of roots (c'/a with a = 1).
    const double halfChord = std::sqrt(discriminant);
    const double q = -halfB - std::copysign(halfChord, halfB);
    if (q == 0.0) {
        // Only when b' = 0 and the discriminant is 0: a ray starting on the sphere, tangent
        // to it. Both roots are 0, and 0 is not a hit.
        return std::nullopt;
    }
    const double tNear = std::min(power / q, q);
    const double tFar = std::max(power / q, q);

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
    // The hit relative to the centre is l -+ halfChord * d (near / far root): built from these
    // small terms, not from o + t*d - c, which cancels to rounding noise when the sphere is small
    // next to its distance (a radius of 1e-20 one unit away would give 0/0). The point is then
    // put on the sphere along that direction, and the normal is the unit direction itself.
    const bool nearRoot = t == tNear;
    const glm::dvec3 outward = glm::normalize(l + (nearRoot ? -halfChord : halfChord) * d);
    hit.point = sphere.center + r * outward;
    hit.geometricNormal = outward;
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

namespace {

// The nearest-hit order: smaller t first, and on an exact tie the earlier node.
bool isBefore(const Hit& hit, std::size_t index, const std::optional<SceneHit>& nearest) {
    return !nearest || hit.t < nearest->hit.t || (hit.t == nearest->hit.t && index < nearest->nodeIndex);
}

// Calls visit(sceneNodeIndex) for each sphere in every leaf whose box the ray may reach no
// farther than the limit visit last returned (infinity to begin with; a negative limit stops
// the walk). Nearer children are visited first.
template <class Visit>
void forEachSphereAlongRay(const Ray& ray, const Bvh& bvh, Visit&& visit) {
    if (bvh.nodes.empty()) {
        return;
    }
    const BvhTolerance tolerance = bvhTolerance(ray, bvh);
    double limit = kInfinity;
    struct Pending {
        std::uint32_t node;
        double entry;
    };
    std::vector<Pending> stack;
    if (const std::optional<double> entry = bvhBoxEntry(ray, bvh.nodes[0], tolerance.pad)) {
        stack.push_back({0, *entry});
    }
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        if (pending.entry > limit + tolerance.tSlack) {
            continue;  // every sphere in it is hit beyond the limit, if at all
        }
        const BvhNode& node = bvh.nodes[pending.node];
        if (node.isLeaf()) {
            for (std::uint32_t i = 0; i < node.count; ++i) {
                limit = visit(bvh.sphereNodes[node.firstOrSecondChild + i]);
                if (limit < 0.0) {
                    return;
                }
            }
            continue;
        }
        const std::uint32_t first = pending.node + 1;
        const std::uint32_t second = node.firstOrSecondChild;
        const std::optional<double> firstEntry = bvhBoxEntry(ray, bvh.nodes[first], tolerance.pad);
        const std::optional<double> secondEntry = bvhBoxEntry(ray, bvh.nodes[second], tolerance.pad);
        const bool secondIsNearer = secondEntry && (!firstEntry || *secondEntry < *firstEntry);
        // Pushed far child first, so that the near one is popped first.
        if (secondIsNearer) {
            if (firstEntry)
                stack.push_back({first, *firstEntry});
            stack.push_back({second, *secondEntry});
        } else {
            if (secondEntry)
                stack.push_back({second, *secondEntry});
            if (firstEntry)
                stack.push_back({first, *firstEntry});
        }
    }
}

}  // namespace

BvhTolerance bvhTolerance(const Ray& ray, const Bvh& bvh) {
    // intersectSphere's rounding is relative to |origin - centre|, which this bounds.
    const BvhNode& root = bvh.nodes.at(0);
    const double magnitude = largestAbsComponent(ray.origin) +
                             std::max(largestAbsComponent(root.boundsMin), largestAbsComponent(root.boundsMax));
    // pad: a ray that intersectSphere says hits misses the exact sphere by a few units of roundoff
    // of that magnitude at most. tSlack: near a tangent, its t can be off by ~sqrt(roundoff).
    return {1e-9 * magnitude, 1e-6 * magnitude};
}

std::optional<double> bvhBoxEntry(const Ray& ray, const BvhNode& node, double pad) {
    double entry = -kInfinity;
    double exit = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = node.boundsMin[axis] - pad;
        const double high = node.boundsMax[axis] + pad;
        const double origin = ray.origin[axis];
        const double direction = ray.direction[axis];
        if (direction == 0.0) {
            if (origin < low || origin > high) {
                return std::nullopt;  // parallel to this slab and outside it
            }
            continue;
        }
        double tLow = (low - origin) / direction;
        double tHigh = (high - origin) / direction;
        if (tLow > tHigh) {
            std::swap(tLow, tHigh);
        }
        entry = std::max(entry, tLow);
        exit = std::min(exit, tHigh);
    }
    if (entry > exit || exit <= 0.0) {
        return std::nullopt;
    }
    return entry;
}

std::optional<SceneHit> findNearestHit(const Ray& ray, const Scene& scene, const Bvh* bvh) {
    std::optional<SceneHit> nearest;
    if (!bvh) {
        for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
            const std::optional<Hit> hit = intersectGeometry(ray, scene.nodes[index].geometry);
            // Strictly smaller replaces, so on an exact tie the earlier node keeps the pixel.
            if (hit && (!nearest || hit->t < nearest->hit.t)) {
                nearest = SceneHit{*hit, index};
            }
        }
        return nearest;
    }

    forEachPlane(scene, bvh, [&](std::size_t index, const Plane& plane) {
        const std::optional<Hit> hit = intersectPlane(ray, plane);
        if (hit && isBefore(*hit, index, nearest)) {
            nearest = SceneHit{*hit, index};
        }
    });
    forEachSphereAlongRay(ray, *bvh, [&](std::uint32_t index) {
        const std::optional<Hit> hit = intersectSphere(ray, std::get<Sphere>(scene.nodes[index].geometry));
        if (hit && isBefore(*hit, index, nearest)) {
            nearest = SceneHit{*hit, index};
        }
        return nearest ? nearest->hit.t : kInfinity;
    });
    return nearest;
}

bool hasSphereHitBefore(const Ray& ray, const Scene& scene, double maxT, const Bvh* bvh) {
    if (!bvh) {
        for (const Node& node : scene.nodes) {
            if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
                const std::optional<Hit> hit = intersectSphere(ray, *sphere);
                if (hit && hit->t < maxT) {
                    return true;
                }
            }
        }
        return false;
    }
    bool found = false;
    forEachSphereAlongRay(ray, *bvh, [&](std::uint32_t index) {
        const std::optional<Hit> hit = intersectSphere(ray, std::get<Sphere>(scene.nodes[index].geometry));
        found = hit && hit->t < maxT;
        return found ? -1.0 : maxT;  // -1 stops the walk
    });
    return found;
}

}  // namespace hexray::cpu
