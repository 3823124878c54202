// Ray/plane and ray/sphere intersection.

// The plane y = height. A ray parallel to it (d.y = +-0) misses; so does any non-finite t.
real intersectPlane(Ray ray, real height) {
#ifdef HEXRAY_NAIVE
    real t = (height - ray.origin.y) / ray.direction.y;  // textbook: +-inf and NaN slip through
    return t > 0.0 ? t : NO_HIT;
#else
    if (ray.direction.y == 0.0) {
        return NO_HIT;
    }
    real t = (height - ray.origin.y) / ray.direction.y;
    return (t > 0.0 && !isinf(t)) ? t : NO_HIT;  // NaN fails t > 0
#endif
}

// Nearest t > 0 on the sphere, or NO_HIT (the far root when the ray starts inside).
real intersectSphere(Ray ray, vec3r center, real radius) {
    vec3r f = ray.origin - center;
#ifdef HEXRAY_NAIVE
    // Textbook b^2 - 4ac: both terms are about |f|^2 and cancel for small or distant spheres;
    // (-b - sqrt)/2a cancels for rays starting near the surface.
    real a = dot(ray.direction, ray.direction);
    real b = 2.0 * dot(f, ray.direction);
    real c = dot(f, f) - radius * radius;
    real discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) {
        return NO_HIT;
    }
    real root = sqrt(discriminant);
    real near = (-b - root) / (2.0 * a);
    real far = (-b + root) / (2.0 * a);
#else
    // The discriminant from the centre's distance to the ray's line (Hearn-Baker) compares r
    // with a quantity of its own size; the roots come from the stable pair q and c/q, so
    // neither is a difference of nearly equal numbers.
    real b = dot(f, ray.direction);
    real lineDistance = length(f - b * ray.direction);
    real discriminant = (radius - lineDistance) * (radius + lineDistance);
    if (discriminant < 0.0) {
        return NO_HIT;
    }
    real root = sqrt(discriminant);
    real q = -b - (b >= 0.0 ? root : -root);
    if (q == 0.0) {
        return NO_HIT;  // tangent at the origin itself
    }
    // |f|^2 - r^2 as a product, so a shadow ray's origin just outside the sphere keeps c > 0.
    real originDistance = length(f);
    real c = (originDistance - radius) * (originDistance + radius);
    real near = min(c / q, q);
    real far = max(c / q, q);
#endif
    if (near > 0.0) {
        return near;
    }
    return far > 0.0 ? far : NO_HIT;
}

real intersectNode(Ray ray, uint index) {
    vec4r geometry = nodes[index].geometry;
    if (nodes[index].kinds.x == GEOMETRY_PLANE) {
        return intersectPlane(ray, geometry.x);
    }
    return intersectSphere(ray, geometry.xyz, geometry.w);
}

// On an exact tie the earlier node keeps the hit (strict <), as the course specifies.
Hit findNearestHit(Ray ray) {
    Hit hit = Hit(NO_HIT, NO_NODE);
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        real t = intersectNode(ray, i);
        if (t < hit.t) {
            hit = Hit(t, i);
        }
    }
    return hit;
}

bool isOccluded(Ray ray, real maxDistance) {
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        if (intersectNode(ray, i) < maxDistance) {
            return true;
        }
    }
    return false;
}
