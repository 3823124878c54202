// Tracing through the host-built BVH over the spheres (host/accel/bvh.h, packed by
// host/gpu/gpu_scene.cpp), in render.comp's HEXRAY_BVH variant (storage-buffer scenes). Planes
// are unbounded, so they stay out of the tree and are tested first.
#ifndef HEXRAY_BVH_GLSL
#define HEXRAY_BVH_GLSL
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_ballot : require

#include "node_tests.glsl"
#include "render_outputs.glsl"
#include "precision.glsl"
#include "ray.glsl"
#include "scene_data.glsl"
#include "shader_interface.h"

struct BvhNode {
    vec3r boundsMin;
    uint firstOrSecondChild;  // leaf: its first sphere in primitiveNodes after the planes; interior: second child
    vec3r boundsMax;
    uint count;               // leaf: number of spheres; interior: 0 (its first child is the next node)
};
layout(std430, set = 0, binding = BVH_BINDING) readonly buffer BvhBlock {
    BvhNode bvhNodes[];
};
// Scene node indices: frame.planeCount planes, then the spheres in leaf order.
layout(std430, set = 0, binding = PRIMITIVE_BINDING) readonly buffer PrimitiveBlock {
    uint primitiveNodes[];
};

// One traversal stack per subgroup, in workgroup memory: a private array indexed at run time
// is lowered by lavapipe into code whose cost grows with the array's length. Every invocation
// of a subgroup writes the same entries, and reads only what it wrote itself. Sized for
// subgroups of one invocation, the worst case.
shared uint bvhStack[WORKGROUP_SIZE * WORKGROUP_SIZE * BVH_STACK_SIZE];
// The slab test's own rounding can shrink a box's exit distance by a few units of roundoff
// (Ize, "Robust BVH ray traversal"); stretching it by this factor keeps grazing rays inside.
const real BOX_EXIT_STRETCH = 1.0 + 8.0 * UNIT_ROUNDOFF;

// 1 / direction, with zero components replaced by a tiny number of either sign: the slab test
// then sees a huge but finite factor and never forms 0 * inf.
vec3r inverseDirection(vec3r direction) {
    const real TINY = real(1e-30);
    return vec3r(1.0) / mix(direction, vec3r(TINY), equal(direction, vec3r(0.0)));
}

// Whether the ray enters the node's box before `limit`; `entry` is where (0 if it starts inside).
bool entersBox(uint index, Ray ray, vec3r inverse, real limit, out real entry) {
    vec3r t0 = (bvhNodes[index].boundsMin - ray.origin) * inverse;
    vec3r t1 = (bvhNodes[index].boundsMax - ray.origin) * inverse;
    vec3r near = min(t0, t1);
    vec3r far = max(t0, t1);
    entry = max(max(near.x, near.y), max(near.z, 0.0));
    real exit = min(min(far.x, far.y), far.z) * BOX_EXIT_STRETCH;
    return entry <= min(exit, limit);
}

// Walks the tree nearest child first, one subgroup (lavapipe: 8 neighbouring pixels) at a
// time: the subgroup visits a node when any of its rays enters the box before that ray's own
// hit, so the walk, the stack and every node fetch are the same for all its invocations (no
// divergence, no per-lane gathers); each ray still tests every sphere it could hit. With
// `anyHit` (shadow rays, whose segment ends at `hit.t` > 0) returns whether any sphere lies
// closer; otherwise narrows `hit` to the nearest one. Camera rays (powerFromHost) take each sphere's power from
// the host; other rays compute it.
bool traverseBvh(Ray ray, bool anyHit, bool powerFromHost, inout Hit hit) {
    vec3r inverse = inverseDirection(ray.direction);
    uint stackBase = gl_SubgroupID * BVH_STACK_SIZE;
    uint depth = 0u;
    real entry;
    uint current = 0u;
    bool visit = subgroupAny(entersBox(0u, ray, inverse, hit.t, entry));
    while (true) {
        if (visit) {
            uint count = bvhNodes[current].count;
            uint link = bvhNodes[current].firstOrSecondChild;
            if (count > 0u) {
                for (uint k = 0u; k < count; ++k) {
                    uint node = primitiveNodes[frame.planeCount + link + k];
                    real power = powerFromHost
                                     ? nodes[node].surface.x
                                     : originPower(ray.origin - nodes[node].geometry.xyz, nodes[node].geometry.w);
                    real t = sphereNodeDistance(ray, node, power);
                    // On an exact tie the lower node index keeps the hit, as the course specifies
                    // ("the earlier node"), whatever order the tree visits them in. A shadow ray's
                    // limit is the light: only what is strictly nearer blocks it.
                    bool tieWon = !anyHit && t == hit.t && t != NO_HIT && node < hit.node;
                    if (t < hit.t || tieWon) {
                        // A blocked shadow ray asks for nothing more: limit 0 enters no box.
                        hit = Hit(anyHit ? 0.0 : t, node);
                    }
                }
                // Leaving only when the whole subgroup is done keeps the loop uniform.
                if (anyHit && subgroupAll(hit.t == 0.0)) {
                    return true;
                }
            } else {
                uint first = current + 1u;
                real firstEntry;
                real secondEntry;
                bool enterFirst = entersBox(first, ray, inverse, hit.t, firstEntry);
                bool enterSecond = entersBox(link, ray, inverse, hit.t, secondEntry);
                bool anyFirst = subgroupAny(enterFirst);
                bool anySecond = subgroupAny(enterSecond);
                if (anyFirst && anySecond) {
                    // Nearest-hit rays go the way most of the subgroup's rays would; shadow rays
                    // stop at any blocker, so their order is not worth a vote.
                    bool preferSecond = enterSecond && (!enterFirst || secondEntry < firstEntry);
                    bool secondNearer = !anyHit && 2u * subgroupBallotBitCount(subgroupBallot(preferSecond)) >
                                                       subgroupBallotBitCount(subgroupBallot(true));
                    bvhStack[stackBase + depth] = secondNearer ? first : link;
                    ++depth;
                    current = secondNearer ? link : first;
                    continue;
                }
                if (anyFirst || anySecond) {
                    current = anyFirst ? first : link;
                    continue;
                }
            }
        }
        if (depth == 0u) {
            return anyHit && hit.t == 0.0;
        }
        --depth;
        // A postponed box is worth opening only if some ray's hit still lies beyond its entry.
        current = subgroupBroadcastFirst(bvhStack[stackBase + depth]);
        visit = subgroupAny(entersBox(current, ray, inverse, hit.t, entry));
    }
}

Hit findNearestHitInBvh(Ray ray) {
    Hit hit = Hit(NO_HIT, NO_NODE);
    for (uint k = 0u; k < frame.planeCount; ++k) {
        uint node = primitiveNodes[k];
        real t = planeNodeDistance(ray, node);
        if (t < hit.t) {  // planes come in scene order: strict < keeps the earlier on a tie
            hit = Hit(t, node);
        }
    }
    traverseBvh(ray, false, true, hit);
    return hit;
}

bool isOccludedInBvh(Ray ray, vec3r target, real distance) {
    for (uint k = 0u; k < frame.planeCount; ++k) {
        if (blocksSegment(ray, primitiveNodes[k], target, distance)) {
            return true;
        }
    }
    Hit blocker = Hit(distance, NO_NODE);
    return traverseBvh(ray, true, false, blocker);
}

#endif  // HEXRAY_BVH_GLSL
