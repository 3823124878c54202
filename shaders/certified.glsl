// Certified float32 (a kernel generated for f32-certified): each decision the kernel makes checks
// how far it lies from going the other way against CERTAINTY_BOUND, a bound on float32's error per
// unit of the decision's scale (host/gpu/scene_constant_values.cpp). The margins and scales are the
// ones the CPU reference measures (host/cpu/cpu_margins.h), here in the kernel's own float. A pixel
// with any decision in doubt is flagged (kernel_main.glsl), and the host renders it again in f64:
// a flagged pixel costs its vector nothing here, and the f64 pass runs on the flagged pixels alone.
// The kernel defines CERTAINTY_BOUND before including this file.
#ifndef HEXRAY_CERTIFIED_GLSL
#define HEXRAY_CERTIFIED_GLSL

#include "checker.glsl"
#include "precision.glsl"
#include "ray.glsl"

bool pixelInDoubt = false;

// A decision `distance` from its boundary is certain when float32's error there, CERTAINTY_BOUND
// per unit of `scale`, cannot carry it across. NaN is doubt; a decision that does not apply
// (`applies` false) is none.
void certify(bool applies, real distance, real scale) {
    pixelInDoubt = pixelInDoubt || (applies && !(distance >= CERTAINTY_BOUND * scale));
}

// ---------------------------------------------------------------- camera rays

// How far roundoff moves a camera ray's hit on a sphere, per unit: |c - o| + r over the cosine
// between the ray and the normal, which is the half-chord over r (infinite for a tangent or a miss).
// Written as sphereDistanceFast (intersect.glsl) forms its terms, so that the compiler shares them.
real sphereHitScale(Ray ray, vec3r center, real radius) {
    vec3r f = ray.origin - center;
    real b = dot(f, ray.direction);
    vec3r l = f - b * ray.direction;
    real halfChord = sqrt(max(radius * radius - dot(l, l), 0.0));
    return (length(f) + radius) * radius / halfChord;
}

// The same for a plane: |p - o| over the cosine |d.y|.
real planeHitScale(Ray ray, real t) {
    return t / abs(ray.direction.y);
}

// Whether a camera ray meets the plane is the sign of d.y, whose roundoff is a few units.
void certifyPlaneCrossing(Ray ray) {
    certify(true, abs(ray.direction.y), 1.0);
}

// Whether the ray meets the sphere: the line's distance |l| from the centre against r, where the
// sphere reaches in front of the eye. |r - |l|| is |r^2 - |l|^2| / (r + |l|), at least the
// quarter discriminant over max(|f|, r) + r (|l| <= |f|): no square root, a constant denominator,
// and a margin at most (|f| + r) / 2r times too small, which errs toward doubt.
void certifySilhouette(Ray ray, vec3r center, real radius) {
    vec3r f = ray.origin - center;
    real b = dot(f, ray.direction);
    vec3r l = f - b * ray.direction;
    real discriminant = radius * radius - dot(l, l);  // as sphereDistanceFast forms it
    real clearance = abs(discriminant) * (1.0 / (max(length(f), radius) + radius));
    certify(radius - b > 0.0, clearance, length(f) + radius);
}

// Which node is nearest: every other hit must lie farther than the nearest by more than both their
// errors (cpu_margins.h nearestNodeMargin). Kept as the nearest hit's interval t +- bound * scale and
// the lowest end of the others'.
struct NearestCertainty {
    real nearestLow;
    real nearestHigh;
    real othersLow;
};

NearestCertainty noNearest() {
    return NearestCertainty(REAL_MAX, -REAL_MAX, REAL_MAX);
}

// The hit scale of the nearest node found by the last camera ray: shading's decisions scale with it.
real nearestHitScale = 0.0;

// After node `node`, at `t` (NO_HIT for a miss) with hit scale `scale`, was offered to `hit`.
NearestCertainty offerNearest(NearestCertainty c, Hit hit, uint node, real t, real scale) {
    real low = t == NO_HIT ? REAL_MAX : t - CERTAINTY_BOUND * scale;
    real high = t + CERTAINTY_BOUND * scale;
    bool nearest = hit.node == node;
    c.othersLow = min(c.othersLow, nearest ? c.nearestLow : low);
    c.nearestLow = nearest ? low : c.nearestLow;
    c.nearestHigh = nearest ? high : c.nearestHigh;
    nearestHitScale = nearest ? scale : nearestHitScale;
    return c;
}

void certifyNearest(NearestCertainty c) {
    pixelInDoubt = pixelInDoubt || !(c.othersLow > c.nearestHigh);
}

// ---------------------------------------------------------------- shading

// A plane's checker cell: the distance of (x, z) from the nearest cell edge on each axis, against
// its scale t + |p_u| / |d.y| (the hit slides along the ray, and with d.y) plus the square's size.
void certifyPlaneCell(vec4r checker, vec3r position, Ray ray, real t, bool applies) {
    vec2r cell = planeCell(checker, position);
    vec2r edgeDistance = abs(cell - floor(cell + 0.5)) * checker.x;
    vec2r scale = t + abs(position.xz) / abs(ray.direction.y) + checker.x;
    certify(applies, edgeDistance.x, scale.x);
    certify(applies, edgeDistance.y, scale.y);
}

// Whether the surface faces a light at `distance`: |cos| against the roundoff of the normal and of
// the direction to the light (cpu_margins.h facingMargin).
void certifyFacing(real cosTheta, real normalRoundoff, real directionRoundoff, bool applies) {
    certify(applies, abs(cosTheta), normalRoundoff + directionRoundoff);
}

// A lit light's term: its roundoff against an 8-bit level (unit_roundoff.h LIGHT_TERM_TOLERANCE;
// cpu_margins.h lightTermMargin), with CERTAINTY_MARGIN as every decision here.
void certifyLightTerm(real normalRoundoff, real directionRoundoff, bool applies) {
    real roundoff = (3.0 * directionRoundoff + normalRoundoff) * (LIGHT_TERM_UNITS * CERTAINTY_MARGIN) * UNIT_ROUNDOFF;
    certify(applies, real(LIGHT_TERM_TOLERANCE), roundoff / CERTAINTY_BOUND);
}

// Whether a plane blocks the segment from the point to the light: either end's height above it.
void certifyPlaneSegment(real height, vec3r point, vec3r light, real scale, bool applies) {
    certify(applies, min(abs(point.y - height), abs(light.y - height)), scale + abs(height));
}

// Whether a shadow ray's point end lies clear of a sphere's surface, for every light's test of it
// at once (certifySphereSegment): ||p - c| - r| against CERTAINTY_BOUND times the largest segment
// scale, `farthestSegmentScale` (the hit's scale plus the farthest light's distance) + |c| + r.
// Without a square root, and never larger than the true distance: ||p - c|^2 - r^2| / (|p - c| + r),
// with |p - c| <= t + |c| (the point is t from the eye), the denominator moved across.
bool clearOfSurface(vec3r point, real t, vec4r sphere, real farthestSegmentScale) {
    vec3r fromCenter = point - sphere.xyz;
    real bound = CERTAINTY_BOUND * (farthestSegmentScale + length(sphere.xyz) + sphere.w);
    return abs(dot(fromCenter, fromCenter) - sphere.w * sphere.w) >= bound * (t + length(sphere.xyz) + sphere.w);
}

// Whether a sphere blocks the segment from the light toward the point (`f` the light minus the
// centre, `power` the light's power |f|^2 - r^2, `direction` toward the point, `segmentLength` to it):
// the line against the silhouette where it matters, and each end's distance from the surface
// (cpu_margins.h sphereCrossingMargins; the point's end from clearOfSurface), each against
// CERTAINTY_BOUND times `scale` + |c| + r. The line's clearance |r - |l|| comes from the quarter
// discriminant b^2 - power = r^2 - |l|^2 as in certifySilhouette: no square root, never larger than
// the true one (errs toward doubt).
void certifySphereSegment(vec3r f, real power, vec3r center, real radius, vec3r direction, real segmentLength,
                          bool pointEndCertain, real scale, bool applies) {
    real bound = CERTAINTY_BOUND * (scale + length(center) + radius);
    real b = dot(f, direction);
    real discriminant = b * b - power;  // as the shadow tests form it
    bool clearanceCertain = abs(discriminant) * (1.0 / (max(length(f), radius) + radius)) >= bound;
    bool lightEndCertain = abs(length(f) - radius) >= bound;
    // A line that misses: where its closest point lies outside the segment, the nearer end must
    // reach the sphere too (either certain suffices). A line that cuts: the reference counts the
    // clearance only while the chord meets the segment; here always, which errs toward doubt.
    bool closestInside = b <= 0.0 && -b <= segmentLength;
    bool nearerEndCertain = b > 0.0 ? lightEndCertain : pointEndCertain;
    bool missCertain = clearanceCertain || (!closestInside && nearerEndCertain);
    bool cutCertain = clearanceCertain && lightEndCertain && pointEndCertain;
    pixelInDoubt = pixelInDoubt || (applies && !(discriminant < 0.0 ? missCertain : cutCertain));
}

#endif  // HEXRAY_CERTIFIED_GLSL
