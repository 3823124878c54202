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
    return nodeGeometryKind(i) == GEOMETRY_PLANE;
}

// Distance along the ray to a sphere (centre, radius); `power` is the ray origin's (originPower).
real sphereDistanceFor(Ray ray, vec4r sphere, real power) {
#ifdef HEXRAY_TEXTBOOK
    return sphereDistanceTextbook(ray, sphere.xyz, sphere.w);
#else
    return sphereDistance(ray, sphere.xyz, sphere.w, power);
#endif
}

real sphereNodeDistance(Ray ray, uint i, real power) {
    return sphereDistanceFor(ray, nodeGeometry(i), power);
}

real planeNodeDistance(Ray ray, uint i) {
#ifdef HEXRAY_TEXTBOOK
    return planeDistanceTextbook(ray, nodeGeometry(i).x);
#else
    return planeDistance(ray, nodeGeometry(i).x);
#endif
}

// Distance along a camera ray to node i. Camera rays all start at the eye, whose power with
// respect to each sphere the host computed.
real cameraRayDistance(Ray ray, uint i) {
    return isPlaneNode(i) ? planeNodeDistance(ray, i) : sphereNodeDistance(ray, i, nodeEyePower(i));
}

#endif  // HEXRAY_NODE_TESTS_GLSL
