#version 450
// hexray's data-driven kernel, for scenes too large for a generated one (see
// host/kernels/kernel_generator.h): every ray tests every node in a loop over the storage buffers,
// or, with HEXRAY_CANDIDATES, only the nodes listed for its direction (candidates.glsl): the
// same tests on the same nodes in the same order, less the nodes it cannot meet. Compiled at
// build time for f32, f64 (HEXRAY_F64) and f32-naive (HEXRAY_TEXTBOOK), with and without
// HEXRAY_CANDIDATES.
#extension GL_GOOGLE_include_directive : require

// Its loops may pass lavapipe's limit: the host may render a pixel's lights in batches.
#define HEXRAY_LIGHT_BATCHES

#include "checker.glsl"
#include "kernel_policies.glsl"
#include "lighting.glsl"
#include "node_tests.glsl"
#include "scene_data.glsl"
#include "surface.glsl"
#ifdef HEXRAY_CANDIDATES
#include "candidates.glsl"
#endif

// What shading reads of the hit's node.
struct HitNode {
    vec4r geometry;
    real eyePower;
    bool plane;
    uint look;
};

HitNode readHitNode(uint node) {
    return HitNode(nodeGeometry(node), nodeEyePower(node), isPlaneNode(node), nodeLook(node));
}

#ifdef HEXRAY_CANDIDATES
// The sphere record of the last findNearestHit's hit (NO_NODE: a plane, or none). A shadow ray
// tells the hit's own sphere by its record, so reads no candidate's node.
uint hitRecord;
// The last findNearestHit's hit's node, from its record or plane: the nodes lie in the scene's
// order, the records in space's, so neighbouring pixels' hits are rarely near in the nodes.
HitNode hitNode;
#endif

Hit findNearestHit(Ray ray) {
    Hit hit = Hit(NO_HIT, NO_NODE);
#ifdef HEXRAY_CANDIDATES
    hitNode = HitNode(vec4r(0.0), 0.0, true, 0u);
    CandidateRange planes = planeCandidates();
    for (uint k = planes.first; k < planes.end; ++k) {
        uint node = candidateEntry(k);
        vec4r geometry = nodeGeometry(node);
        Hit nearest = nearer(hit, planeDistanceOf(ray, geometry.x), node);
        if (nearest.node != hit.node) {
            hitNode = HitNode(geometry, 0.0, true, nodeLook(node));
        }
        hit = nearest;
    }
    hitRecord = NO_NODE;
    CandidateRange spheres = cameraCandidates(vec3(ray.direction));
    for (uint k = spheres.first; k < spheres.end; ++k) {
        uint record = candidateEntry(k);
        vec4r sphere = candidateSphereGeometry(record);
        vec3r fromSphere = ray.origin - sphere.xyz;
        if (spheres.depthOrdered && liesBeyond(dot(fromSphere, fromSphere), sphere.w, hit.t)) {
            break;  // so do the rest
        }
        // The fast test needs no eye power: the rest of the record is read only for a sphere that
        // may be the nearest (its node breaks a tie).
        CandidateSphereNode s;
        if (!FAST_CAMERA_TESTS) {
            s = candidateSphereNode(record);
        }
        real t = sphereDistanceFor(ray, sphere, s.eyePower);
        if (t <= hit.t && t != NO_HIT) {
            if (FAST_CAMERA_TESTS) {
                s = candidateSphereNode(record);
            }
            Hit nearest = nearer(hit, t, s.node);
            if (nearest.node != hit.node) {  // a sphere has one record
                hitRecord = record;
                hitNode = HitNode(sphere, s.eyePower, false, s.look);
            }
            hit = nearest;
        }
    }
#else
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        hit = nearer(hit, cameraRayDistance(ray, i), i);
    }
#endif
    return hit;
}

HitNode hitNodeOf(Hit hit) {
#ifdef HEXRAY_CANDIDATES
    return hitNode;
#else
    return readHitNode(hit.node);
#endif
}

// Whether plane `node` lies strictly between the surface and the light at `light`.
bool planeBlocks(uint node, LightPath path, vec3r light) {
#ifdef HEXRAY_TEXTBOOK
    return planeDistanceTextbook(path.shadowRay, nodeGeometry(node).x) < path.shadowLength;
#else
    return planeSeparates(nodeGeometry(node).x, path.shadowRay.origin, light);
#endif
}

// Whether `sphere` (centre, radius) shadows the surface of the hit from the light at `light`.
// Robust: tested from the light toward the surface, the same origin for every pixel, and not the
// hit's own sphere (`isHitsSphere`) when the eye sees it from outside (`hitSeenFromOutside`,
// castsShadow). The textbook test starts at the surface, as a course does.
bool sphereBlocks(vec4r sphere, bool isHitsSphere, LightPath path, vec3r light, bool hitSeenFromOutside) {
#ifdef HEXRAY_TEXTBOOK
    return sphereDistanceTextbook(path.shadowRay, sphere.xyz, sphere.w) < path.shadowLength;
#else
    bool crosses = sphereCrossesSegmentFor(light - sphere.xyz, sphere, -path.shadowRay.direction, path.shadowLength);
    return castsShadow(crosses, isHitsSphere, hitSeenFromOutside);
#endif
}

// Light `light`, at `lightAt` with `power` (scene_data.glsl's lightPosition and lightPower).
bool isOccluded(uint light, vec4r lightAt, vec4r power, LightPath path, Hit hit, HitNode node) {
    vec3r position = lightAt.xyz;
    bool hitSeenFromOutside = node.eyePower > 0.0;  // planes: 0
    // A surface facing away from the light gets nothing from it, whatever lies between: no tests.
#ifdef HEXRAY_TEXTBOOK
    bool blocked = !path.facing;
    bool planesMayShadow = true;
#else
    bool blocked = !path.facing || lightAt.w > 0.0;  // a sphere holding the eye hides it
    bool planesMayShadow = !(power.w > 0.0);
#endif
#ifdef HEXRAY_CANDIDATES
    CandidateRange planes = planeCandidates();
    uint planesEnd = planesMayShadow ? planes.end : planes.first;
    for (uint k = planes.first; k < planesEnd && !blocked; ++k) {
        blocked = planeBlocks(candidateEntry(k), path, position);
    }
    CandidateRange spheres = lightCandidates(light, vec3(-path.shadowRay.direction), float(path.shadowLength));
    for (uint k = spheres.first; k < spheres.end && !blocked; ++k) {
        uint record = candidateEntry(k);
        blocked = sphereBlocks(candidateSphereGeometry(record), record == hitRecord, path, position, hitSeenFromOutside);
    }
#else
    for (uint i = 0u; i < frame.nodeCount && !blocked; ++i) {
        blocked = isPlaneNode(i) ? planesMayShadow && planeBlocks(i, path, position)
                                 : sphereBlocks(nodeGeometry(i), i == hit.node, path, position, hitSeenFromOutside);
    }
#endif
    return blocked;
}

real candidateDistance(Ray ray, uint node) {
    return cameraRayDistance(ray, node);
}

Surface surfaceOf(Ray ray, Hit hit, HitNode node) {
    vec4r geometry = node.geometry;
#ifdef HEXRAY_TEXTBOOK
    return node.plane ? planeSurfaceTextbook(ray, hit.t) : sphereSurfaceTextbook(ray, hit.t, geometry);
#else
    real eyePower = node.eyePower;
    Surface sphere = FAST_CAMERA_TESTS ? sphereSurfaceFast(ray, hit.t, geometry) : sphereSurface(ray, geometry, eyePower);
    sphere.shadowOrigin = sphereShadowOrigin(sphere, geometry, !(eyePower > 0.0));
    return node.plane ? planeSurface(ray, hit.t, geometry.x) : sphere;
#endif
}

Surface hitSurface(Ray ray, Hit hit) {
    return surfaceOf(ray, hit, readHitNode(hit.node));
}

vec3 shadeLights(Ray ray, Hit hit, uint firstLight, uint endLight, inout vec3 irradiance, inout uint flags) {
    HitNode node = hitNodeOf(hit);
    uint look = node.look;
    uint shader = lookShaderKind(look);
    vec3 albedo = lookColor1(look);
    if (shader == SHADER_CONSTANT) {
        return albedo;
    }
    Surface s = surfaceOf(ray, hit, node);
    vec4r checker = lookChecker(look);
    bool odd = node.plane ? isOddPlaneCell(checker, s.position) : isOddSphereCell(checker, s.outwardNormal);
    if (shader == SHADER_CHECKER && odd) {
        albedo = lookColor2(look);
        flags |= ODD_CHECKER_BIT;
    }
    traceSurface(s, albedo);
    for (uint i = firstLight; i < endLight; ++i) {
        vec4r lightAt = lightPosition(i);
        vec4r power = lightPower(i);
        LightPath path = lightPath(s, lightAt.xyz);
        irradiance += lightTerm(i, power, path, isOccluded(i, lightAt, power, path, hit, node), flags);
    }
    return litColor(albedo, irradiance);
}

vec3 shade(Ray ray, Hit hit, out uint flags) {
    flags = 0u;
    vec3 irradiance = frame.ambient.rgb;
    return shadeLights(ray, hit, 0u, frame.lightCount, irradiance, flags);
}

#include "kernel_main.glsl"
