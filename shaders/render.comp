#version 450
// hexray's data-driven kernel, for scenes too large for a generated one (see
// host/gpu/kernel_generator.h): every ray tests every node in a loop over the storage buffers,
// or, with HEXRAY_BVH, walks a BVH over the spheres. Compiled at build time for f32, f64
// (HEXRAY_F64) and f32-naive (HEXRAY_TEXTBOOK), with and without HEXRAY_BVH.
#extension GL_GOOGLE_include_directive : require

#include "checker.glsl"
#include "lighting.glsl"
#include "node_tests.glsl"
#include "scene_data.glsl"
#include "surface.glsl"
#ifdef HEXRAY_BVH
#include "bvh.glsl"
#endif

Hit findNearestHit(Ray ray) {
#ifdef HEXRAY_BVH
    return findNearestHitInBvh(ray);
#else
    Hit hit = Hit(NO_HIT, NO_NODE);
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        real t = cameraRayDistance(ray, i);
        // On an exact tie the earlier node keeps the hit (strict <), as the course specifies.
        if (t < hit.t) {
            hit = Hit(t, i);
        }
    }
    return hit;
#endif
}

// Whether anything lies strictly between the ray's origin and `target`, `distance` away.
bool isOccluded(Ray ray, vec3r target, real distance) {
#ifdef HEXRAY_BVH
    return isOccludedInBvh(ray, target, distance);
#else
    bool blocked = false;
    for (uint i = 0u; i < frame.nodeCount && !blocked; ++i) {
        blocked = blocksSegment(ray, i, target, distance);
    }
    return blocked;
#endif
}

real candidateDistance(Ray ray, uint node) {
    return cameraRayDistance(ray, node);
}

Surface hitSurface(Ray ray, Hit hit) {
    vec4r geometry = nodes[hit.node].geometry;
#ifdef HEXRAY_TEXTBOOK
    return isPlaneNode(hit.node) ? planeSurfaceTextbook(ray, hit.t) : sphereSurfaceTextbook(ray, hit.t, geometry);
#else
    Surface sphere = sphereSurface(ray, geometry, nodes[hit.node].surface.x);
    // Every node is tested for every shadow ray, the sphere itself included.
    sphere.shadowOrigin = shadowOriginOffSphere(sphere, geometry);
    return isPlaneNode(hit.node) ? planeSurface(ray, hit.t, geometry.x) : sphere;
#endif
}

vec3 shade(Ray ray, Hit hit, out uint flags) {
    Node node = nodes[hit.node];
    flags = 0u;
    if (node.kinds.y == SHADER_CONSTANT) {
        return node.color1.rgb;
    }
    Surface s = hitSurface(ray, hit);
    vec3 albedo = node.color1.rgb;
    bool odd = isPlaneNode(hit.node) ? isOddPlaneCell(node.checker, s.position)
                                     : isOddSphereCell(node.checker, s.outwardNormal);
    if (node.kinds.y == SHADER_CHECKER && odd) {
        albedo = node.color2.rgb;
        flags |= ODD_CHECKER_BIT;
    }
    traceSurface(s, albedo);
    vec3 irradiance = frame.ambient.rgb;
    for (uint i = 0u; i < frame.lightCount; ++i) {
        LightPath path = lightPath(s, lights[i].position.xyz);
        bool shadowed = isOccluded(path.shadowRay, lights[i].position.xyz, path.shadowLength);
        irradiance += lightTerm(i, lights[i].power, path, shadowed, flags);
    }
    return albedo * min(irradiance, vec3(MAX_LIGHT_TERM));
}

#include "kernel_main.glsl"
