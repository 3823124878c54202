// Light batches, for the data-driven kernel (render.comp defines HEXRAY_LIGHT_BATCHES): where one
// invocation could not run a pixel's loops whole within lavapipe's limit (host/gpu/loop_budget.h),
// the host renders a band in several dispatches, each the samples [band.firstSample,
// band.endSample) of every pixel and, of each, the lights [band.firstLight, band.endLight): whole
// samples at a time, or one sample in several batches of lights. What a pixel has so far passes
// from one dispatch to the next in the carry buffer, as the floats the single pass holds in its
// registers, added to in the same order: the image is the single pass's, bit for bit.
#ifndef HEXRAY_LIGHT_BATCHES_GLSL
#define HEXRAY_LIGHT_BATCHES_GLSL

#include "ray.glsl"
#include "render_outputs.glsl"
#include "scene_data.glsl"
#include "shader_interface.h"

// GpuPixelCarry (host/layout/gpu_layout.h).
struct PixelCarry {
    vec3 sum;         // the colours of the pixel's samples before this dispatch's
    uint flags;       // the sample's class flags so far
    vec3 irradiance;  // the sample's irradiance so far: the ambient and the lights before this dispatch's
    uint unused;
};

// One per pixel of the band; used only by renders in several dispatches.
layout(std430, set = 0, binding = CARRY_BINDING) buffer CarryBlock {
    PixelCarry carry[];
};

// Whether the host renders each band in several dispatches (LightBatches::splits). Without, a
// dispatch renders every sample and light of its pixels, and the carrying folds away when the
// pipeline is made: lavapipe then unrolls the sample loop, which its bounds from the band kept it
// from (docs/performance.md, "The data-driven kernel on lavapipe").
layout(constant_id = LIGHT_BATCHES_ID) const bool LIGHTS_IN_BATCHES = false;

#define FIRST_SAMPLE (LIGHTS_IN_BATCHES ? band.firstSample : 0u)
#define END_SAMPLE (LIGHTS_IN_BATCHES ? band.endSample : SAMPLES_PER_PIXEL)
#define LAST_LIGHTS (!LIGHTS_IN_BATCHES || band.endLight == frame.lightCount)

// A hit's colour lit by lights [firstLight, endLight) on top of `irradiance`, which they are added
// to; `flags` gains ODD_CHECKER_BIT and their lit bits (render.comp).
vec3 shadeLights(Ray ray, Hit hit, uint firstLight, uint endLight, inout vec3 irradiance, inout uint flags);

// A sample's colour once its last batch of lights is in; before that, its irradiance and flags
// are carried to the next. The background's light loop is left empty: its colour is not this one.
vec3 shadeSample(Ray ray, Hit hit, bool background, uint index, out uint flags) {
    vec3 irradiance = frame.ambient.rgb;
    flags = 0u;
    if (LIGHTS_IN_BATCHES && band.firstLight > 0u) {
        irradiance = carry[index].irradiance;
        flags = carry[index].flags;
    }
    uint endLight = background ? band.firstLight : band.endLight;
    vec3 color = shadeLights(ray, hit, band.firstLight, endLight, irradiance, flags);
    if (!LAST_LIGHTS) {
        carry[index].irradiance = irradiance;
        carry[index].flags = flags;
    }
    return color;
}

vec3 carriedSum(uint index) {
    return carry[index].sum;
}

void carrySum(uint index, vec3 sum) {
    carry[index].sum = sum;
}

#endif  // HEXRAY_LIGHT_BATCHES_GLSL
