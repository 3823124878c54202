// One point light seen from a surface: its direction, 1/r^2 falloff and Lambert's cosine, and
// what the light then adds (the shadow test itself is the kernel's).
#ifndef HEXRAY_LIGHTING_GLSL
#define HEXRAY_LIGHTING_GLSL

#include "inspect_hooks.glsl"
#include "precision.glsl"
#include "ray.glsl"
#include "surface.glsl"

struct LightPath {
    real r2;            // squared distance from the surface point to the light
    real cosTheta;      // 0 when the light is on the point
    bool facing;        // the surface faces the light
    Ray shadowRay;      // from the surface's shadow origin toward the light
    real shadowLength;  // the shadow ray's distance to the light; 0 when not facing
};

// For a surface whose shadow rays start at the point itself (planes and spheres seen from outside,
// in the robust formulation): one square root serves cos theta, the shadow ray's direction and its
// length.
LightPath lightPathFromPoint(Surface s, vec3r lightPosition) {
    LightPath path;
    vec3r toLight = lightPosition - s.position;
    path.r2 = dot(toLight, toLight);
    real inverseDistance = inversesqrt(path.r2);
    // A light exactly at the point (r2 = 0) has no direction and contributes nothing.
    real cosTheta = dot(s.normal, toLight) * inverseDistance;
    path.facing = path.r2 > 0.0 && cosTheta > 0.0;
    path.cosTheta = path.r2 == 0.0 ? 0.0 : cosTheta;
    path.shadowRay = Ray(s.position, toLight * inverseDistance);
    // A surface facing away asks about an empty segment, whose answer is unused (straight-line
    // code: lavapipe runs a skipped branch anyway).
    path.shadowLength = path.facing ? path.r2 * inverseDistance : 0.0;
    return path;
}

// Any surface: Lambert's cosine and the falloff from the point itself, as the reference shades, the
// shadow ray from the shadow origin. Off a sphere seen from inside that lies ten or more units of
// roundoff of the sphere's coordinates away (shadowOriginOffSphere): nothing to a shadow test, but
// beside a light that close to the point a visible change of both (cos theta 2 % low at
// differential seed 2008707).
LightPath lightPath(Surface s, vec3r lightPosition) {
    LightPath path = lightPathFromPoint(s, lightPosition);
    vec3r fromOrigin = lightPosition - s.shadowOrigin;
    real originR2 = dot(fromOrigin, fromOrigin);
    real inverseDistance = inversesqrt(originR2);
    path.shadowRay = Ray(s.shadowOrigin, fromOrigin * inverseDistance);
    // A light on the shadow origin itself asks about an empty segment too.
    path.shadowLength = path.facing && originR2 > 0.0 ? originR2 * inverseDistance : 0.0;
    return path;
}

// Light terms and their sum are capped just below float's limit: a light nearly touching the
// point would give inf, and a zero colour channel times inf NaN. A term that large saturates the
// pixel anyway.
const float MAX_LIGHT_TERM = 3.0e38;

// A lit shader's colour: the albedo (up to 1e10 per channel) times the capped irradiance, capped
// again so that the colour stays finite.
vec3 litColor(vec3 albedo, vec3 irradiance) {
    return min(albedo * min(irradiance, vec3(MAX_LIGHT_TERM)), vec3(MAX_LIGHT_TERM));
}

// Light `index`'s part of the irradiance; sets its lit bit in `flags` and records it in a trace.
// In the kernel's arithmetic: in f64 the power and cos / r^2 can each lie beyond float's range
// (5e49 and 1e-50) where their product does not. cos / r^2 is capped (finite) first, so that a
// zero power channel gives 0, not NaN.
vec3 lightTerm(uint index, vec4r power, LightPath path, bool shadowed, inout uint flags) {
    bool lit = path.facing && !shadowed;
    vec3r term = power.rgb * min(path.cosTheta / path.r2, REAL_MAX);
    vec3 contribution = lit ? vec3(min(term, vec3r(MAX_LIGHT_TERM))) : vec3(0.0);
    uint status = path.r2 == 0.0 ? TRACE_LIGHT_AT_POINT
                : !path.facing   ? TRACE_LIGHT_FACING_AWAY
                : shadowed       ? TRACE_LIGHT_SHADOWED
                                 : TRACE_LIGHT_LIT;
    traceLight(index, status, path.cosTheta, path.r2, path.shadowLength, contribution);
    if (lit && index < CLASSIFIED_LIGHTS) {
        flags |= 2u << index;
    }
    return contribution;
}

#endif  // HEXRAY_LIGHTING_GLSL
