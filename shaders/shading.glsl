// Constant, Lambert and Checker shaders under point lights with 1/r^2 falloff and shadows.

// Sum of ambient and every point light the surface sees, weighted by cos(theta) / r^2.
// Sets the lit bit (see ClassBlock) of each light that contributes.
vec3 incidentLight(Surface s, inout uint flags) {
    vec3 sum = frame.ambient.rgb;
    for (uint i = 0u; i < lightCount(); ++i) {
        vec3r toLight = lights[i].position.xyz - s.position;
        real r2 = dot(toLight, toLight);
        if (r2 == 0.0) {
            traceLight(i, TRACE_LIGHT_AT_POINT, 0.0, r2, 0.0, vec3(0.0));
            continue;  // a light exactly at the point: no direction, no contribution
        }
        real cosTheta = dot(s.normal, toLight) * inversesqrt(r2);
        if (cosTheta <= 0.0) {
            traceLight(i, TRACE_LIGHT_FACING_AWAY, cosTheta, r2, 0.0, vec3(0.0));
            continue;  // facing away: dark whether or not anything is in between
        }
        vec3r shadowPath = lights[i].position.xyz - s.shadowOrigin;
        real shadowLength = length(shadowPath);
        if (isOccluded(Ray(s.shadowOrigin, shadowPath / shadowLength), lights[i].position.xyz, shadowLength)) {
            traceLight(i, TRACE_LIGHT_SHADOWED, cosTheta, r2, shadowLength, vec3(0.0));
            continue;
        }
        sum += lights[i].power.rgb * float(cosTheta / r2);
        traceLight(i, TRACE_LIGHT_LIT, cosTheta, r2, shadowLength, lights[i].power.rgb * float(cosTheta / r2));
        if (i < CLASSIFIED_LIGHTS) {
            flags |= 2u << i;
        }
    }
    return sum;
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
