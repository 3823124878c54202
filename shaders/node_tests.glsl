// Intersection tests against node i of the scene's node array, in the formulation the
// data-driven kernel (render.comp) was compiled for: the robust one, or the textbook one with
// HEXRAY_TEXTBOOK (f32-naive).
#ifndef HEXRAY_NODE_TESTS_GLSL
#define HEXRAY_NODE_TESTS_GLSL

#include "intersect.glsl"
#include "precision.glsl"
#include "ray.glsl"
#include "scene_data.glsl"

bool isPlaneNode(uint i) {
    return nodes[i].kinds.x == GEOMETRY_PLANE;
}

// Distance along the ray to sphere node i; `power` is the ray origin's (originPower).
real sphereNodeDistance(Ray ray, uint i, real power) {
    vec4r sphere = nodes[i].geometry;
#ifdef HEXRAY_TEXTBOOK
    return sphereDistanceTextbook(ray, sphere.xyz, sphere.w);
#else
    return sphereDistance(ray, sphere.xyz, sphere.w, power);
#endif
}

real planeNodeDistance(Ray ray, uint i) {
#ifdef HEXRAY_TEXTBOOK
    return planeDistanceTextbook(ray, nodes[i].geometry.x);
#else
    return planeDistance(ray, nodes[i].geometry.x);
#endif
}

// Distance along a camera ray to node i. Camera rays all start at the eye, whose power with
// respect to each sphere the host computed.
real cameraRayDistance(Ray ray, uint i) {
    return isPlaneNode(i) ? planeNodeDistance(ray, i) : sphereNodeDistance(ray, i, nodes[i].surface.x);
}

// Whether node i lies on the segment from the ray's origin to `target`, `distance` away.
bool blocksSegment(Ray ray, uint i, vec3r target, real distance) {
    vec4r geometry = nodes[i].geometry;
    if (isPlaneNode(i)) {
#ifdef HEXRAY_TEXTBOOK
        return planeDistanceTextbook(ray, geometry.x) < distance;
#else
        return planeSeparates(geometry.x, ray.origin, target);
#endif
    }
    return sphereNodeDistance(ray, i, originPower(ray.origin - geometry.xyz, geometry.w)) < distance;
}

#endif  // HEXRAY_NODE_TESTS_GLSL
