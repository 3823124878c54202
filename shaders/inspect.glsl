// The inspection modes' own work, after shading.glsl (see inspect_hooks.glsl).

// What the AOV buffer holds for the pixel's first sample.
void writeAov(uint index, Ray ray, Hit hit) {
    if (hit.node == NO_NODE) {
        aovs[index] = vec4(0.0);
        return;
    }
    Surface s = surfaceAt(ray, hit, nodes[hit.node], isPlane(hit.node));
    aovs[index] = vec4(vec3(s.normal), float(hit.t));
}

// One invocation replays the requested pixel as main() renders it, recording every node's
// candidate t (the function findNearestHit uses without a BVH), the hit it chose, and,
// through the hooks in shade(), the surface and each light's terms for the requested sample.
void traceMain() {
    if (gl_GlobalInvocationID.xy != uvec2(0u)) {
        return;
    }
    uvec2 pixel = trace.header.request.xy;
    uint tracedSample = trace.header.request.z;
    vec3 sum = vec3(0.0);
    for (uint sampleIndex = 0u; sampleIndex < SAMPLES_PER_PIXEL; ++sampleIndex) {
        Ray ray = primaryRay(pixel, sampleIndex);
        traceActive = sampleIndex == tracedSample;
        Hit hit = findNearestHit(ray);
        if (traceActive && hit.node != NO_NODE) {
            // Constant shaders never build a Surface; lit ones overwrite this with their own.
            traceSurface(surfaceAt(ray, hit, nodes[hit.node], isPlane(hit.node)), nodes[hit.node].color1.rgb);
        }
        uint flags = 0u;
        vec3 color = hit.node == NO_NODE ? frame.background.rgb : shade(ray, hit, flags);
        sum += color;
        if (traceActive) {
            trace.header.rayOrigin.xyz = ray.origin;
            trace.header.rayDirection.xyz = ray.direction;
            trace.header.hitPosition.w = hit.t;
            trace.header.result.yz = uvec2(hit.node, flags);
            trace.header.sampleColor = vec4(color, 1.0);
            for (uint i = 0u; i < nodeCount(); ++i) {
                trace.entries[i].values = vec4r(cameraRayDistance(ray, i), 0.0, 0.0, 0.0);
                trace.entries[i].status = uvec4(isPlane(i) ? GEOMETRY_PLANE : GEOMETRY_SPHERE, 0u, 0u, 0u);
            }
        }
    }
    traceActive = false;
    trace.header.pixelColor = vec4(sum / float(SAMPLES_PER_PIXEL), 1.0);
    trace.header.result.x = 1u;
}
