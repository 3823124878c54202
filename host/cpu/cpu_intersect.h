#pragma once
// Ray/surface intersection for the CPU reference renderer, in double precision.
// Written independently of the shader so that a bug in either shows up as a difference.

#include <cstddef>
#include <optional>

#include <glm/vec3.hpp>

#include "accel/bvh.h"
#include "scene/scene.h"

namespace hexray::inline cpu {

// A half-line origin + t * direction, t > 0. `direction` must have unit length:
// the sphere test relies on it (a = dot(d, d) = 1) and t is then a distance.
struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};
};

// Where a ray meets a surface.
struct Hit {
    double t = 0.0;                   // distance along the ray
    glm::dvec3 point{0.0};            // exactly on the surface as far as double allows
    glm::dvec3 geometricNormal{0.0};  // sphere: outward; plane: +Y
    glm::dvec3 facingNormal{0.0};     // the geometric normal turned toward the ray's origin side
};

// The plane y = plane.height. Misses rays parallel to it and rays leaving it behind.
std::optional<Hit> intersectPlane(const Ray& ray, const Plane& plane);

// The nearest root t > 0 (the far one when the ray starts inside), found with the
// cancellation-free discriminant and root pair; the hit point is reprojected onto the sphere.
std::optional<Hit> intersectSphere(const Ray& ray, const Sphere& sphere);

std::optional<Hit> intersectGeometry(const Ray& ray, const Geometry& geometry);

struct SceneHit {
    Hit hit;
    std::size_t nodeIndex = 0;  // into Scene::nodes
};

// The nearest hit over all nodes; on an exact distance tie the earlier node wins. With a BVH
// (built from this scene by buildBvh) the spheres are found through it, with the same answer
// bit for bit: its box tests are widened so that they never skip a sphere intersectSphere would
// report, and the tie rule is applied explicitly instead of by loop order.
std::optional<SceneHit> findNearestHit(const Ray& ray, const Scene& scene, const Bvh* bvh = nullptr);

// Whether any sphere has a hit with t < maxT (shadow rays; planes are decided by a sign test,
// see isSegmentClear). With a BVH it stops at the first such hit.
bool hasSphereHitBefore(const Ray& ray, const Scene& scene, double maxT, const Bvh* bvh = nullptr);

// The BVH's boxes as the traversal tests them, widened against the rounding of intersectSphere:
// by `pad` in space, and by `tSlack` in the distance at which a box is entered. Both are a
// large multiple of the rounding error (relative 1e-9 and 1e-6 of the coordinates' magnitude).
struct BvhTolerance {
    double pad = 0.0;
    double tSlack = 0.0;
};
BvhTolerance bvhTolerance(const Ray& ray, const Bvh& bvh);

// Where the ray enters the node's box widened by `pad`; nothing when it misses it or leaves it
// at t <= 0. Conservative: a sphere inside the box that intersectSphere reports at t is not
// missed, and is entered at or before t + tSlack.
std::optional<double> bvhBoxEntry(const Ray& ray, const BvhNode& node, double pad);

// Calls visit(index, plane) for every plane node, in scene order: from the BVH's list when
// there is one, so that a ray in a scene of many spheres does not scan every node.
template <typename Visit>
void forEachPlane(const Scene& scene, const Bvh* bvh, Visit&& visit) {
    if (bvh) {
        for (const std::uint32_t index : bvh->planeNodes) {
            visit(std::size_t{index}, std::get<Plane>(scene.nodes[index].geometry));
        }
        return;
    }
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (const auto* plane = std::get_if<Plane>(&scene.nodes[index].geometry)) {
            visit(index, *plane);
        }
    }
}

}  // namespace hexray::cpu
