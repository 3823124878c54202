// Inspection outputs (host/layout/gpu_layout.h, "Inspection"): per-pixel AOVs for `render --aov`,
// and a trace of one pixel for `hexray pixel`. traceSurface and traceLight are called while
// shading; both compile away unless OUTPUT_MODE asks for a trace.
#ifndef HEXRAY_INSPECT_HOOKS_GLSL
#define HEXRAY_INSPECT_HOOKS_GLSL

#include "precision.glsl"
#include "render_outputs.glsl"
#include "scene_data.glsl"
#include "shader_interface.h"
#include "surface.glsl"

// .xyz shading normal, .w hit t (shader units); zero for the background.
layout(std430, set = 0, binding = AOV_BINDING) writeonly buffer AovBlock {
    vec4 aovs[];
};

struct TraceHeader {
    uvec4 request;     // .xy pixel, .z sample (written by the host)
    uvec4 result;      // .x written, .y hit node, .z class flags, .w in doubt (f32-certified)
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
    uvec4 status;  // node: .x geometry kind; light: .x a TRACE_LIGHT_ status
};

layout(std430, set = 0, binding = TRACE_BINDING) buffer TraceBlock {
    TraceHeader header;
    TraceEntry entries[];  // frame.nodeCount candidates, then frame.lightCount lights
} trace;

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
        uint entry = frame.nodeCount + light;
        trace.entries[entry].values = vec4r(cosTheta, r2, shadowLength, 0.0);
        trace.entries[entry].color = vec4(contribution, 0.0);
        trace.entries[entry].status = uvec4(status, 0u, 0u, 0u);
    }
}

#endif  // HEXRAY_INSPECT_HOOKS_GLSL
