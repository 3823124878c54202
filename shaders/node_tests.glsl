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

// Whether every sphere lies far enough from the eye (or around it) for the fast test, and from
// every light: the plan's decisions (render_plan.h, RenderPlan::fastCameraTests and
// fastShadowTests), as a generated kernel's per sphere.
layout(constant_id = FAST_CAMERA_TESTS_ID) const bool FAST_CAMERA_TESTS = false;
layout(constant_id = FAST_SHADOW_TESTS_ID) const bool FAST_SHADOW_TESTS = false;

// Whether a sphere (centre, radius) meets the segment from a light `f` from its centre, along
// `direction`, `segmentLength` long.
bool sphereCrossesSegmentFor(vec3r f, vec4r sphere, vec3r direction, real segmentLength) {
    return FAST_SHADOW_TESTS ? sphereCrossesSegmentFast(f, sphere.w, direction, segmentLength)
                             : sphereCrossesSegment(f, sphere.w, originPower(f, sphere.w), direction, segmentLength);
}

// Distance along a camera ray to a sphere (centre, radius); `power` is the eye's (originPower).
real sphereDistanceFor(Ray ray, vec4r sphere, real power) {
#ifdef HEXRAY_TEXTBOOK
    return sphereDistanceTextbook(ray, sphere.xyz, sphere.w);
#else
    return FAST_CAMERA_TESTS ? sphereDistanceFast(ray, sphere.xyz, sphere.w)
                             : sphereDistance(ray, sphere.xyz, sphere.w, power);
#endif
}

real sphereNodeDistance(Ray ray, uint i, real power) {
    return sphereDistanceFor(ray, nodeGeometry(i), power);
}

real planeDistanceOf(Ray ray, real height) {
#ifdef HEXRAY_TEXTBOOK
    return planeDistanceTextbook(ray, height);
#else
    return planeDistance(ray, height);
#endif
}

real planeNodeDistance(Ray ray, uint i) {
    return planeDistanceOf(ray, nodeGeometry(i).x);
}

// Distance along a camera ray to node i. Camera rays all start at the eye, whose power with
// respect to each sphere the host computed.
real cameraRayDistance(Ray ray, uint i) {
    return isPlaneNode(i) ? planeNodeDistance(ray, i) : sphereNodeDistance(ray, i, nodeEyePower(i));
}

#endif  // HEXRAY_NODE_TESTS_GLSL
