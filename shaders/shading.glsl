// Constant, Lambert and Checker shaders under point lights with 1/r^2 falloff and shadows.

// Sum of ambient and every point light the surface sees, weighted by cos(theta) / r^2.
// Sets the lit bit (see ClassBlock) of each light that contributes.
vec3 incidentLight(Surface s, inout uint flags) {
    // Terms are capped just below float's limit: a light nearly touching the point would give inf,
    // and a zero colour channel times inf NaN. A term that large saturates the pixel anyway.
    const float MAX_LIGHT_TERM = 3.0e38;
    vec3 sum = frame.ambient.rgb;
    for (uint i = 0u; i < lightCount(); ++i) {
        vec3r toLight = lights[i].position.xyz - s.position;
        real r2 = dot(toLight, toLight);
        // A light exactly at the point (r2 = 0) has no direction and contributes nothing.
        real cosTheta = dot(s.normal, toLight) * inversesqrt(r2);
        bool facing = r2 > 0.0 && cosTheta > 0.0;
        vec3r shadowPath = lights[i].position.xyz - s.shadowOrigin;
        real shadowLength = length(shadowPath);
        // Straight-line code, as lavapipe runs a skipped branch anyway. A surface facing away
        // asks about an empty segment (the answer is unused), for which a BVH walk opens no box.
        bool shadowed = isOccluded(Ray(s.shadowOrigin, shadowPath / shadowLength), lights[i].position.xyz,
                                   facing ? shadowLength : 0.0);
        bool lit = facing && !shadowed;
        vec3 contribution = lit ? lights[i].power.rgb * min(float(cosTheta / r2), MAX_LIGHT_TERM) : vec3(0.0);
        sum += contribution;
        uint status = r2 == 0.0 ? TRACE_LIGHT_AT_POINT
                    : !facing   ? TRACE_LIGHT_FACING_AWAY
                    : shadowed  ? TRACE_LIGHT_SHADOWED
                                : TRACE_LIGHT_LIT;
        traceLight(i, status, r2 == 0.0 ? 0.0 : cosTheta, r2, facing ? shadowLength : 0.0, contribution);
        if (lit && i < CLASSIFIED_LIGHTS) {
            flags |= 2u << i;
        }
    }
    return min(sum, vec3(MAX_LIGHT_TERM));
}

// 0 or 1 for a number holding an integer; exact at any magnitude (x/2 and floor are exact).
real parity(real wholeNumber) {
    return mod(wholeNumber, 2.0);
}

bool isOddChecker(uint index, Node node, Surface s) {
    vec2r cell;
    if (isCheckerPlane(index)) {
        // u = x, v = z in world space: the eye's cell offset comes from the host in double.
        cell = floor(node.checker.yz + s.position.xz / node.checker.x);
    } else {
        // Longitude and latitude in degrees. GLSL has atan and asin in float only, so the
        // f64 variant computes the angles in float too. Latitude is asin(n.y), computed as
        // atan(n.y, |n.xz|): drivers may approximate asin coarsely (Mesa's is off by ~1e-4
        // rad, enough to move checker edges by a visible fraction of a pixel), atan closely.
        vec3 n = vec3(s.outwardNormal);
        vec2 uv = degrees(vec2(atan(n.x, n.z), atan(n.y, length(n.xz))));
        cell = floor(vec2r(uv) / node.checker.x);
    }
    return parity(parity(cell.x) + parity(cell.y) + node.checker.w) != 0.0;
}

vec3 shade(Ray ray, Hit hit, out uint flags) {
    Node node = nodes[hit.node];
    flags = 0u;
    if (isConstantShaded(hit.node)) {
        return node.color1.rgb;
    }
    Surface s = surfaceAt(ray, hit, node, isLitPlane(hit.node));
    vec3 albedo = node.color1.rgb;
    if (isCheckerShaded(hit.node) && isOddChecker(hit.node, node, s)) {
        albedo = node.color2.rgb;
        flags |= ODD_CHECKER_BIT;
    }
    traceSurface(s, albedo);
    return albedo * incidentLight(s, flags);
}
