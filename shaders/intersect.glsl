// Ray/plane and ray/sphere intersection.

// The plane y = height. A ray parallel to it (d.y = +-0) misses; so does any non-finite t.
real intersectPlane(Ray ray, real height) {
    real t = (height - ray.origin.y) / ray.direction.y;
#ifdef HEXRAY_NAIVE
    return t > 0.0 ? t : NO_HIT;  // textbook: +-inf and NaN slip through
#else
    return (ray.direction.y != 0.0 && t > 0.0 && !isinf(t)) ? t : NO_HIT;  // NaN fails t > 0
#endif
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

// Nearest t > 0 on the sphere, or NO_HIT (the far root when the ray starts inside).
// `power` is originPower of the ray's origin.
real intersectSphere(Ray ray, vec3r center, real radius, real power) {
    vec3r f = ray.origin - center;
    // Straight-line code (no early returns): lavapipe runs every path anyway, and a return
    // from inside a branch costs it extra bookkeeping.
#ifdef HEXRAY_NAIVE
    // Textbook b^2 - 4ac: both terms are about |f|^2 and cancel for small or distant spheres;
    // (-b - sqrt)/2a cancels for rays starting near the surface.
    real a = dot(ray.direction, ray.direction);
    real b = 2.0 * dot(f, ray.direction);
    real c = dot(f, f) - radius * radius;
    real discriminant = b * b - 4.0 * a * c;
    real root = sqrt(max(discriminant, 0.0));
    real near = (-b - root) / (2.0 * a);
    real far = (-b + root) / (2.0 * a);
    bool meets = discriminant >= 0.0;
#else
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
#endif
    real t = near > 0.0 ? near : far;
    return (meets && t > 0.0) ? t : NO_HIT;
}

// A plane blocks a segment exactly when its ends lie strictly on opposite sides: no division,
// so a light lying in the plane is never blocked by it through rounding.
bool planeSeparates(real height, vec3r origin, vec3r target) {
    real originSide = origin.y - height;
    real targetSide = target.y - height;
    return (originSide < 0.0 && targetSide > 0.0) || (originSide > 0.0 && targetSide < 0.0);
}

// Distance along a camera ray to node i. Camera rays all start at the eye, whose power with
// respect to each sphere the host computed.
real cameraRayDistance(Ray ray, uint i) {
    vec4r geometry = nodes[i].geometry;
    return isPlane(i) ? intersectPlane(ray, geometry.x)
                      : intersectSphere(ray, geometry.xyz, geometry.w, nodes[i].surface.x);
}

// Whether node i lies on the segment from the ray's origin to `target`, `distance` away.
bool blocksSegment(Ray ray, uint i, vec3r target, real distance) {
    vec4r geometry = nodes[i].geometry;
    if (isPlane(i)) {
#ifdef HEXRAY_NAIVE
        return intersectPlane(ray, geometry.x) < distance;
#else
        return planeSeparates(geometry.x, ray.origin, target);
#endif
    }
    return intersectSphere(ray, geometry.xyz, geometry.w, originPower(ray.origin - geometry.xyz, geometry.w)) < distance;
}
