// Inspection outputs (host/gpu/gpu_layout.h, "Inspection"): per-pixel AOVs for `render --aov`,
// and a trace of one pixel for `hexray pixel`. Included before shading.glsl, whose hooks call
// traceSurface and traceLight; both compile away unless OUTPUT_MODE asks for a trace.

const uint OUTPUT_LINEAR_CLASSES_AND_AOV = 3u;
const uint OUTPUT_TRACE = 4u;

// .xyz shading normal, .w hit t (shader units); zero for the background.
layout(std430, set = 0, binding = 8) writeonly buffer AovBlock {
    vec4 aovs[];
};

struct TraceHeader {
    uvec4 request;     // .xy pixel, .z sample (written by the host)
    uvec4 result;      // .x written, .y hit node, .z class flags
    vec4r rayOrigin;
    vec4r rayDirection;
    vec4r hitPosition;  // .w t
    vec4r hitNormal;
    vec4r shadowOrigin;
    vec4 albedo;
    vec4 sampleColor;
    vec4 pixelColor;
};

struct TraceEntry {
    vec4r values;  // node: .x t; light: cos theta, r^2, shadow ray length
    vec4 color;    // light: contribution
    uvec4 status;  // node: .x geometry kind; light: .x TraceLightStatus
};

layout(std430, set = 0, binding = 9) buffer TraceBlock {
    TraceHeader header;
    TraceEntry entries[];  // nodeCount() candidates, then lightCount() lights
} trace;

const uint TRACE_LIGHT_LIT = 1u;
const uint TRACE_LIGHT_FACING_AWAY = 2u;
const uint TRACE_LIGHT_SHADOWED = 3u;
const uint TRACE_LIGHT_AT_POINT = 4u;

// True only while the traced sample is being shaded.
bool traceActive = false;

bool tracing() {
    return OUTPUT_MODE == OUTPUT_TRACE && traceActive;
}

void traceSurface(Surface s, vec3 albedo) {
    if (tracing()) {
        trace.header.hitPosition.xyz = s.position;
        trace.header.hitNormal.xyz = s.normal;
        trace.header.shadowOrigin.xyz = s.shadowOrigin;
        trace.header.albedo = vec4(albedo, 1.0);
    }
}

void traceLight(uint light, uint status, real cosTheta, real r2, real shadowLength, vec3 contribution) {
    if (tracing()) {
        uint entry = nodeCount() + light;
        trace.entries[entry].values = vec4r(cosTheta, r2, shadowLength, 0.0);
        trace.entries[entry].color = vec4(contribution, 0.0);
        trace.entries[entry].status = uvec4(status, 0u, 0u, 0u);
    }
}
