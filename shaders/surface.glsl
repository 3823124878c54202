// What shading needs to know about a hit: where it is, which way it faces, and where a
// shadow ray may start without hitting the same surface again.

struct Surface {
    vec3 position;
    vec3 normal;         // facing the side the ray came from
    vec3 outwardNormal;  // spheres: away from the centre (texture coordinates use it)
    vec3 shadowOrigin;
};

// float32 unit roundoff, times a few operations: a bound on the error of a reprojected point.
const float REPROJECTION_ERROR = 5.0 * 5.9604645e-8;

Surface surfaceAt(Ray ray, Hit hit) {
    Node node = nodes[hit.node];
    vec3 approximate = ray.origin + hit.t * ray.direction;
    Surface s;
    if (node.kinds.x == GEOMETRY_PLANE) {
        // Snapped exactly onto the plane, a shadow ray from here cannot hit it again (t = 0),
        // so no offset is needed.
        s.position = vec3(approximate.x, node.geometry.x, approximate.z);
        s.outwardNormal = vec3(0.0, ray.direction.y < 0.0 ? 1.0 : -1.0, 0.0);
        s.normal = s.outwardNormal;
        s.shadowOrigin = s.position;
        return s;
    }
    vec3 center = node.geometry.xyz;
    float radius = node.geometry.w;
    s.outwardNormal = normalize(approximate - center);
    s.position = center + radius * s.outwardNormal;  // reprojected onto the sphere
    s.normal = dot(s.outwardNormal, ray.direction) > 0.0 ? -s.outwardNormal : s.outwardNormal;
    // Push off by the point's own error bound (it scales with the coordinates), twice over so
    // the rounding of the addition cannot pull it back: never a fixed epsilon.
    vec3 error = REPROJECTION_ERROR * (abs(center) + abs(radius * s.outwardNormal));
    float offset = 2.0 * dot(abs(s.outwardNormal), error);
    s.shadowOrigin = s.position + offset * s.normal;
    return s;
}
