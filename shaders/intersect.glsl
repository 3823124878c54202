// Ray/plane and ray/sphere intersection: the robust forms, the textbook ones (f32-naive), and a
// fast form for spheres whose conditioning does not need the robust one (host/gpu/render_plan.h
// decides which node gets which).
#ifndef HEXRAY_INTERSECT_GLSL
#define HEXRAY_INTERSECT_GLSL

#include "precision.glsl"
#include "ray.glsl"

// The plane y = height. A ray parallel to it (d.y = +-0) misses; so does any non-finite t.
real planeDistance(Ray ray, real height) {
    real t = (height - ray.origin.y) / ray.direction.y;
    return (ray.direction.y != 0.0 && t > 0.0 && !isinf(t)) ? t : NO_HIT;  // NaN fails t > 0
}

// The textbook plane test: +-inf and NaN slip through.
real planeDistanceTextbook(Ray ray, real height) {
    real t = (height - ray.origin.y) / ray.direction.y;
    return t > 0.0 ? t : NO_HIT;
}

// The power of a point with respect to a sphere, |f|^2 - r^2 for f = point - centre, as a
// product so that a point just outside (a shadow ray's origin) keeps it positive.
real originPower(vec3r f, real radius) {
    real distance = length(f);
    return (distance - radius) * (distance + radius);
}

// Nearest t > 0 on the sphere, or NO_HIT (the far root when the ray starts inside). `power` is
// originPower of the ray's origin. Straight-line code (no early returns): lavapipe runs every
// path anyway, and a return from inside a branch costs it extra bookkeeping.
real sphereDistance(Ray ray, vec3r center, real radius, real power) {
    vec3r f = ray.origin - center;
    // The discriminant from the centre's distance to the ray's line (Hearn-Baker) compares r
    // with a quantity of its own size; the roots come from the stable pair q and c/q, so
    // neither is a difference of nearly equal numbers.
    real b = dot(f, ray.direction);
    real lineDistance = length(f - b * ray.direction);
    real discriminant = (radius - lineDistance) * (radius + lineDistance);
    real root = sqrt(max(discriminant, 0.0));
    real q = -b - (b >= 0.0 ? root : -root);
    real near = min(power / q, q);
    real far = max(power / q, q);
    bool meets = discriminant >= 0.0 && q != 0.0;  // q = 0: tangent at the origin itself
    real t = near > 0.0 ? near : far;
    return (meets && t > 0.0) ? t : NO_HIT;
}

// The fast form, b^2 - power with the power from the host: accurate while the origin is
// neither far from the sphere against its radius (b^2 and the power would cancel) nor close
// to its surface from outside (the near root would); see render_plan.h.
real sphereDistanceFast(Ray ray, vec3r center, real power) {
    real b = dot(ray.origin - center, ray.direction);
    real discriminant = b * b - power;
    real root = sqrt(max(discriminant, 0.0));
    real near = -b - root;
    real t = near > 0.0 ? near : root - b;
    return (discriminant >= 0.0 && t > 0.0) ? t : NO_HIT;
}

// Textbook b^2 - 4ac (f32-naive): both terms are about |f|^2 and cancel for small or distant
// spheres; (-b - sqrt)/2a cancels for rays starting near the surface.
real sphereDistanceTextbook(Ray ray, vec3r center, real radius) {
    vec3r f = ray.origin - center;
    real a = dot(ray.direction, ray.direction);
    real b = 2.0 * dot(f, ray.direction);
    real c = dot(f, f) - radius * radius;
    real discriminant = b * b - 4.0 * a * c;
    real root = sqrt(max(discriminant, 0.0));
    real near = (-b - root) / (2.0 * a);
    real far = (-b + root) / (2.0 * a);
    real t = near > 0.0 ? near : far;
    return (discriminant >= 0.0 && t > 0.0) ? t : NO_HIT;
}

// Whether the sphere's surface crosses the segment from a ray's origin to `segmentLength` along
// its unit `direction`, strictly inside it. `f` is the origin minus the centre and `power` the
// origin's power |f|^2 - r^2, both the same for every pixel when the origin is a light. Robust:
// the discriminant and roots as in sphereDistance.
bool sphereCrossesSegment(vec3r f, real radius, real power, vec3r direction, real segmentLength) {
    real b = dot(f, direction);
    real lineDistance = length(f - b * direction);
    real discriminant = (radius - lineDistance) * (radius + lineDistance);
    real root = sqrt(max(discriminant, 0.0));
    real q = -b - (b >= 0.0 ? root : -root);
    real first = power / q;
    bool crossesAt = (first > 0.0 && first < segmentLength) || (q > 0.0 && q < segmentLength);
    return discriminant >= 0.0 && q != 0.0 && crossesAt;
}

// The same in the fast form (see sphereDistanceFast).
bool sphereCrossesSegmentFast(vec3r f, real power, vec3r direction, real segmentLength) {
    real b = dot(f, direction);
    real discriminant = b * b - power;
    real root = sqrt(max(discriminant, 0.0));
    real near = -b - root;
    real far = root - b;
    bool crossesAt = (near > 0.0 && near < segmentLength) || (far > 0.0 && far < segmentLength);
    return discriminant >= 0.0 && crossesAt;
}

// A plane blocks a segment exactly when its ends lie strictly on opposite sides: no division,
// so a light lying in the plane is never blocked by it through rounding.
bool planeSeparates(real height, vec3r origin, vec3r target) {
    real originSide = origin.y - height;
    real targetSide = target.y - height;
    return (originSide < 0.0 && targetSide > 0.0) || (originSide > 0.0 && targetSide < 0.0);
}

#endif  // HEXRAY_INTERSECT_GLSL
