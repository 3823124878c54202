// Constant, Lambert and Checker shaders under point lights with 1/r^2 falloff and shadows.

// Sum of ambient and every point light the surface sees, weighted by cos(theta) / r^2.
vec3 incidentLight(Surface s) {
    vec3 sum = frame.ambient.rgb;
    for (uint i = 0u; i < frame.lightCount; ++i) {
        vec3 toLight = lights[i].position.xyz - s.position;
        float r2 = dot(toLight, toLight);
        if (r2 == 0.0) {
            continue;  // a light exactly at the point: no direction, no contribution
        }
        float cosTheta = dot(s.normal, toLight) * inversesqrt(r2);
        if (cosTheta <= 0.0) {
            continue;  // facing away: dark whether or not anything is in between
        }
        vec3 shadowPath = lights[i].position.xyz - s.shadowOrigin;
        float shadowLength = length(shadowPath);
        if (isOccluded(Ray(s.shadowOrigin, shadowPath / shadowLength), shadowLength)) {
            continue;
        }
        sum += lights[i].power.rgb * (cosTheta / r2);
    }
    return sum;
}

// 0 or 1 for a float holding an integer; exact at any magnitude (x/2 and floor are exact).
float parity(float wholeNumber) {
    return mod(wholeNumber, 2.0);
}

vec3 checkerColor(Node node, Surface s) {
    float size = node.checker.x;
    vec2 cell;
    if (node.kinds.x == GEOMETRY_PLANE) {
        // u = x, v = z in world space: the eye's cell offset comes from the host in double.
        cell = floor(node.checker.yz + s.position.xz / size);
    } else {
        vec3 n = s.outwardNormal;
        vec2 uv = degrees(vec2(atan(n.x, n.z), asin(clamp(n.y, -1.0, 1.0))));
        cell = floor(uv / size);
    }
    float odd = parity(parity(cell.x) + parity(cell.y) + node.checker.w);
    return odd == 0.0 ? node.color1.rgb : node.color2.rgb;
}

vec3 shade(Ray ray, Hit hit) {
    Node node = nodes[hit.node];
    if (node.kinds.y == SHADER_CONSTANT) {
        return node.color1.rgb;
    }
    Surface s = surfaceAt(ray, hit);
    vec3 albedo = node.kinds.y == SHADER_CHECKER ? checkerColor(node, s) : node.color1.rgb;
    return albedo * incidentLight(s);
}
