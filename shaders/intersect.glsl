// Ray/plane and ray/sphere intersection in forms that stay accurate in float32.

// The plane y = height. A ray parallel to it (d.y = +-0) misses; so does any non-finite t.
float intersectPlane(Ray ray, float height) {
    if (ray.direction.y == 0.0) {
        return NO_HIT;
    }
    float t = (height - ray.origin.y) / ray.direction.y;
    return (t > 0.0 && !isinf(t)) ? t : NO_HIT;  // NaN fails t > 0
}

// Nearest t > 0 on the sphere, or NO_HIT. The textbook b^2 - 4ac cancels catastrophically
// for small or distant spheres; instead the discriminant comes from the centre's distance to
// the ray's line (Hearn-Baker) and the roots from the stable pair q and c/q.
float intersectSphere(Ray ray, vec3 center, float radius) {
    vec3 f = ray.origin - center;
    float b = dot(f, ray.direction);
    float lineDistance = length(f - b * ray.direction);
    float discriminant = (radius - lineDistance) * (radius + lineDistance);
    if (discriminant < 0.0) {
        return NO_HIT;
    }
    float root = sqrt(discriminant);
    float q = -b - (b >= 0.0 ? root : -root);
    if (q == 0.0) {
        return NO_HIT;  // tangent at the origin itself
    }
    // |f|^2 - r^2 as a product, so a shadow ray's origin just outside the sphere keeps c > 0.
    float originDistance = length(f);
    float c = (originDistance - radius) * (originDistance + radius);
    float t0 = c / q;
    float t1 = q;
    float near = min(t0, t1);
    float far = max(t0, t1);
    if (near > 0.0) {
        return near;
    }
    return far > 0.0 ? far : NO_HIT;
}

float intersectNode(Ray ray, uint index) {
    vec4 geometry = nodes[index].geometry;
    if (nodes[index].kinds.x == GEOMETRY_PLANE) {
        return intersectPlane(ray, geometry.x);
    }
    return intersectSphere(ray, geometry.xyz, geometry.w);
}

// On an exact tie the earlier node keeps the hit (strict <), as the course specifies.
Hit findNearestHit(Ray ray) {
    Hit hit = Hit(NO_HIT, NO_NODE);
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        float t = intersectNode(ray, i);
        if (t < hit.t) {
            hit = Hit(t, i);
        }
    }
    return hit;
}

bool isOccluded(Ray ray, float maxDistance) {
    for (uint i = 0u; i < frame.nodeCount; ++i) {
        if (intersectNode(ray, i) < maxDistance) {
            return true;
        }
    }
    return false;
}
