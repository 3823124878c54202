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

// r^2 - |l|^2 = b^2 - power (the quarter discriminant, l the centre's offset to the ray's closest
// point), in whichever form has the smaller first-order rounding error: (r - |l|)(r + |l|) errs by
// about 6u r(|b| + r), which suits small or distant spheres; b^2 - power by about 6u |b||f| + u|power|
// (|f| <= |b| + |l|), which suits a ray starting on or near the sphere, and a large sphere seen
// from close by, where |l| is within rounding of r. Both are computed and one selected: no branch.
real sphereDiscriminant(real b, real lineDistance, real radius, real power) {
    real fromLine = (radius - lineDistance) * (radius + lineDistance);
    real fromPower = b * b - power;
    bool powerIsTighter = 6.0 * abs(b) * (abs(b) + lineDistance) + abs(power) < 6.0 * radius * (abs(b) + radius);
    return powerIsTighter ? fromPower : fromLine;
}

// Nearest t > 0 on the sphere, or NO_HIT (the far root when the ray starts inside). `power` is
// originPower of the ray's origin. Straight-line code (no early returns): lavapipe runs every
// path anyway, and a return from inside a branch costs it extra bookkeeping.
real sphereDistance(Ray ray, vec3r center, real radius, real power) {
    vec3r f = ray.origin - center;
    // The discriminant in its more accurate form for this ray; the roots come from the stable
    // pair q and c/q, so neither is a difference of nearly equal numbers.
    real b = dot(f, ray.direction);
    real lineDistance = length(f - b * ray.direction);
    real discriminant = sphereDiscriminant(b, lineDistance, radius, power);
    real root = sqrt(max(discriminant, 0.0));
    real q = -b - (b >= 0.0 ? root : -root);
    real near = min(power / q, q);
    real far = max(power / q, q);
    bool meets = discriminant >= 0.0 && q != 0.0;  // q = 0: tangent at the origin itself
    real t = near > 0.0 ? near : far;
    return (meets && t > 0.0) ? t : NO_HIT;
}

// The fast form for a ray whose origin is well away from the sphere's surface (outside by a
// quarter of the radius, or inside within half of it; see render_plan.cpp): the Hearn-Baker
// discriminant r^2 - |l|^2, whose error is that of l itself (a difference of vectors, never of
// squares of the distance), and the root itself, which then is a sum of terms that do not cancel.
real sphereDistanceFast(Ray ray, vec3r center, real radius) {
    vec3r f = ray.origin - center;
    real b = dot(f, ray.direction);
    vec3r l = f - b * ray.direction;
    real discriminant = radius * radius - dot(l, l);
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
    real discriminant = sphereDiscriminant(b, lineDistance, radius, power);
    real root = sqrt(max(discriminant, 0.0));
    real q = -b - (b >= 0.0 ? root : -root);
    real first = power / q;
    bool crossesAt = (first > 0.0 && first < segmentLength) || (q > 0.0 && q < segmentLength);
    return discriminant >= 0.0 && q != 0.0 && crossesAt;
}

// The same from an origin well away from the surface and at most a few tens of radii away (see
// render_plan.cpp), in the cheapest form: b^2 - power, with the power from the host in double. From
// outside, both roots lie on one side of the origin and the segment meets the sphere when the near
// one lies inside it; from inside, the far root is the only one ahead.
bool sphereCrossesSegmentFromOutside(vec3r f, real power, vec3r direction, real segmentLength) {
    real b = dot(f, direction);
    real discriminant = b * b - power;
    real near = -b - sqrt(max(discriminant, 0.0));
    return discriminant >= 0.0 && near > 0.0 && near < segmentLength;
}

bool sphereCrossesSegmentFromInside(vec3r f, real power, vec3r direction, real segmentLength) {
    real b = dot(f, direction);
    real far = sqrt(b * b - power) - b;  // power < 0: the discriminant is positive
    return far < segmentLength;
}

// The fast form of sphereCrossesSegment, for an origin (a light) well away from the sphere's surface
// as sphereDistanceFast's: the same discriminant and roots, the nearest root ahead (the far one from
// inside) within the segment.
bool sphereCrossesSegmentFast(vec3r f, real radius, vec3r direction, real segmentLength) {
    real b = dot(f, direction);
    vec3r l = f - b * direction;
    real discriminant = radius * radius - dot(l, l);
    real root = sqrt(max(discriminant, 0.0));
    real near = -b - root;
    real t = near > 0.0 ? near : root - b;
    return discriminant >= 0.0 && t > 0.0 && t < segmentLength;
}

// A plane blocks a segment exactly when its ends lie strictly on opposite sides: no division,
// so a light lying in the plane is never blocked by it through rounding.
bool planeSeparates(real height, vec3r origin, vec3r target) {
    real originSide = origin.y - height;
    real targetSide = target.y - height;
    return (originSide < 0.0 && targetSide > 0.0) || (originSide > 0.0 && targetSide < 0.0);
}

#endif  // HEXRAY_INTERSECT_GLSL
