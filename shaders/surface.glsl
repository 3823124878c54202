// What shading needs to know about a hit: where it is, which way it faces, and where a
// shadow ray may start without hitting the same surface again.
#ifndef HEXRAY_SURFACE_GLSL
#define HEXRAY_SURFACE_GLSL

#include "intersect.glsl"
#include "precision.glsl"
#include "ray.glsl"
#include "shader_interface.h"

struct Surface {
    vec3r position;
    vec3r normal;         // facing the side the ray came from
    vec3r outwardNormal;  // spheres: away from the centre (texture coordinates use it)
    vec3r shadowOrigin;
};

// The course's fixed nudge along the normal (textbook, shader_interface.h).
const real SHADOW_EPSILON = real(TEXTBOOK_SHADOW_NUDGE);
// A bound on the rounding error of a reprojected sphere point, in units of its coordinates.
const real REPROJECTION_ERROR = gamma(5);

vec3r planeNormalFacing(Ray ray) {
    return vec3r(0.0, ray.direction.y < 0.0 ? 1.0 : -1.0, 0.0);
}

// Snapped exactly onto the plane, a shadow ray from here cannot hit it again (t = 0), so no
// offset is needed.
Surface planeSurface(Ray ray, real t, real height) {
    vec3r approximate = ray.origin + t * ray.direction;
    Surface s;
    s.outwardNormal = planeNormalFacing(ray);
    s.normal = s.outwardNormal;
    s.position = vec3r(approximate.x, height, approximate.z);
    s.shadowOrigin = s.position;
    return s;
}

Surface planeSurfaceTextbook(Ray ray, real t) {
    Surface s;
    s.outwardNormal = planeNormalFacing(ray);
    s.normal = s.outwardNormal;
    s.position = ray.origin + t * ray.direction;
    s.shadowOrigin = s.position + SHADOW_EPSILON * s.normal;
    return s;
}

vec3r facing(vec3r outwardNormal, Ray ray) {
    return dot(outwardNormal, ray.direction) > 0.0 ? -outwardNormal : outwardNormal;
}

// The point on the sphere along the outward normal. Its shadow rays start right there: fine when
// the shadow tests leave out the sphere itself, as generated kernels do for a sphere the camera
// sees from outside (see shadowOriginOffSphere otherwise).
Surface reprojectedSphereSurface(Ray ray, vec4r sphere, vec3r outwardNormal) {
    Surface s;
    s.outwardNormal = outwardNormal;
    s.position = sphere.xyz + sphere.w * outwardNormal;  // on the sphere, up to rounding
    s.normal = facing(outwardNormal, ray);
    s.shadowOrigin = s.position;
    return s;
}

// A shadow origin that cannot hit its own sphere again: the point pushed off along the facing
// normal by its own error bound (it scales with the coordinates), twice over so the rounding of
// the addition cannot pull it back: never a fixed epsilon.
vec3r shadowOriginOffSphere(Surface s, vec4r sphere) {
    vec3r error = REPROJECTION_ERROR * (abs(sphere.xyz) + abs(sphere.w * s.outwardNormal));
    real offset = 2.0 * dot(abs(s.outwardNormal), error);
    return s.position + offset * s.normal;
}

// The normal from the intersection's own small quantities: with l the centre's offset to the
// ray's closest point and h the half-chord, the hit is c + l -+ h d (near / far root).
// o + t d - c would subtract numbers as large as the distance, and at 1e7 radii away that
// leaves the normal quantised. Camera rays (`eyePower` is the eye's) take the near root from
// outside, the far one from inside (or on) the sphere, decided by the sign of the eye's power, not
// by comparing t with -b, which rounding cannot tell apart when the half-chord is below an ulp of
// the distance.
Surface sphereSurface(Ray ray, vec4r sphere, real eyePower) {
    vec3r f = ray.origin - sphere.xyz;
    real b = dot(f, ray.direction);
    vec3r l = f - b * ray.direction;
    real lineDistance = length(l);
    real halfChord = sqrt(max(sphereDiscriminant(b, lineDistance, sphere.w, eyePower), 0.0));
    bool nearRoot = eyePower > 0.0;
    vec3r outward = normalize(nearRoot ? l - halfChord * ray.direction : l + halfChord * ray.direction);
    return reprojectedSphereSurface(ray, sphere, outward);
}

// The hit point o + t d and the normal from it: accurate while the sphere is not far from the
// ray's origin against its radius (see sphereDistanceFast).
Surface sphereSurfaceFast(Ray ray, real t, vec4r sphere) {
    Surface s;
    s.position = ray.origin + t * ray.direction;
    s.outwardNormal = normalize(s.position - sphere.xyz);
    s.normal = facing(s.outwardNormal, ray);
    s.shadowOrigin = s.position;
    return s;
}

Surface sphereSurfaceTextbook(Ray ray, real t, vec4r sphere) {
    vec3r approximate = ray.origin + t * ray.direction;
    Surface s;
    s.outwardNormal = normalize(approximate - sphere.xyz);
    s.position = approximate;
    s.normal = facing(s.outwardNormal, ray);
    s.shadowOrigin = s.position + SHADOW_EPSILON * s.normal;
    return s;
}

#endif  // HEXRAY_SURFACE_GLSL
