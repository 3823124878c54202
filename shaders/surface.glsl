// What shading needs to know about a hit: where it is, which way it faces, and where a
// shadow ray may start without hitting the same surface again.

struct Surface {
    vec3r position;
    vec3r normal;         // facing the side the ray came from
    vec3r outwardNormal;  // spheres: away from the centre (texture coordinates use it)
    vec3r shadowOrigin;
};

#ifdef HEXRAY_NAIVE
// The course's fixed nudge along the normal: a no-op once it is below half an ulp of the
// coordinates, and too large for contact shadows near the origin.
const real SHADOW_EPSILON = 1e-4;
#else
// A bound on the rounding error of a reprojected sphere point, in units of its coordinates.
const real REPROJECTION_ERROR = 5.0 * UNIT_ROUNDOFF;
#endif

Surface planeSurfaceAt(Ray ray, Hit hit, Node node) {
    vec3r approximate = ray.origin + hit.t * ray.direction;
    Surface s;
    s.outwardNormal = vec3r(0.0, ray.direction.y < 0.0 ? 1.0 : -1.0, 0.0);
    s.normal = s.outwardNormal;
#ifdef HEXRAY_NAIVE
    s.position = approximate;
    s.shadowOrigin = s.position + SHADOW_EPSILON * s.normal;
#else
    // Snapped exactly onto the plane, a shadow ray from here cannot hit it again (t = 0), so
    // no offset is needed.
    s.position = vec3r(approximate.x, node.geometry.x, approximate.z);
    s.shadowOrigin = s.position;
#endif
    return s;
}

Surface sphereSurfaceAt(Ray ray, Hit hit, Node node) {
    vec3r center = node.geometry.xyz;
    real radius = node.geometry.w;
    Surface s;
#ifdef HEXRAY_NAIVE
    vec3r approximate = ray.origin + hit.t * ray.direction;
    s.outwardNormal = normalize(approximate - center);
    s.position = approximate;
#else
    // The normal from the intersection's own small quantities: with l the centre's offset to
    // the ray's closest point and h the half-chord, the hit is c + l -+ h d (near / far root).
    // o + t d - c would subtract numbers as large as the distance, and at 1e7 radii away
    // that leaves the normal quantised.
    vec3r f = ray.origin - center;
    real b = dot(f, ray.direction);
    vec3r l = f - b * ray.direction;
    real lineDistance = length(l);
    real halfChord = sqrt(max(sphereDiscriminant(b, lineDistance, radius, node.surface.x), 0.0));
    // Camera rays take the near root from outside, the far one from inside (or on) the sphere:
    // decided by the sign of the eye's power, not by comparing t with -b, which rounding
    // cannot tell apart when the half-chord is below an ulp of the distance.
    bool nearRoot = node.surface.x > 0.0;
    s.outwardNormal = normalize(nearRoot ? l - halfChord * ray.direction : l + halfChord * ray.direction);
    s.position = center + radius * s.outwardNormal;  // on the sphere, up to rounding
#endif
    s.normal = dot(s.outwardNormal, ray.direction) > 0.0 ? -s.outwardNormal : s.outwardNormal;
#ifdef HEXRAY_NAIVE
    s.shadowOrigin = s.position + SHADOW_EPSILON * s.normal;
#else
    // Push off by the point's own error bound (it scales with the coordinates), twice over so
    // the rounding of the addition cannot pull it back: never a fixed epsilon.
    vec3r error = REPROJECTION_ERROR * (abs(center) + abs(radius * s.outwardNormal));
    real offset = 2.0 * dot(abs(s.outwardNormal), error);
    s.shadowOrigin = s.position + offset * s.normal;
#endif
    return s;
}

// `node` is the hit node's data; `onPlane` whether it is a plane, asked by the caller in the
// form that folds best for what it knows about the node.
Surface surfaceAt(Ray ray, Hit hit, Node node, bool onPlane) {
    return onPlane ? planeSurfaceAt(ray, hit, node) : sphereSurfaceAt(ray, hit, node);
}
