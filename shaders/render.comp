#version 450
// hexray's renderer: one invocation per pixel traces a primary ray, finds the nearest node,
// shades it under the point lights with shadow rays, and writes linear RGB and what the
// pixel shows. Compiled three times: f32, f64 (HEXRAY_F64) and f32-naive (HEXRAY_NAIVE).
#extension GL_GOOGLE_include_directive : require

layout(local_size_x_id = 0, local_size_y_id = 1) in;

#include "precision.glsl"
#include "scene_data.glsl"
#include "specialization.glsl"
#include "ray.glsl"
#include "camera_ray.glsl"
#include "intersect.glsl"
#include "bvh.glsl"
#include "trace.glsl"
#include "surface.glsl"
#include "inspect_hooks.glsl"
#include "shading.glsl"
#include "encode.glsl"
#include "inspect.glsl"

void main() {
    if (OUTPUT_MODE == OUTPUT_TRACE) {
        traceMain();
        return;
    }
    uvec2 bandPixel = gl_GlobalInvocationID.xy;
    if (bandPixel.x >= frame.imageSize.x || bandPixel.y >= band.rowCount) {
        return;
    }
    // The pixel is classified by its first sample (as the CPU reference does).
    uint node = NO_NODE;
    uint flags = 0u;
    Ray firstRay;
    Hit firstHit;
    vec3 sum = vec3(0.0);
    for (uint sampleIndex = 0u; sampleIndex < SAMPLES_PER_PIXEL; ++sampleIndex) {
        Ray ray = primaryRay(uvec2(bandPixel.x, band.firstRow + bandPixel.y), sampleIndex);
        Hit hit = findNearestHit(ray);
        uint sampleFlags = 0u;
        sum += hit.node == NO_NODE ? frame.background.rgb : shade(ray, hit, sampleFlags);
        if (sampleIndex == 0u) {
            node = hit.node;
            flags = sampleFlags;
            firstRay = ray;
            firstHit = hit;
        }
    }
    vec3 color = sum / float(SAMPLES_PER_PIXEL);
    uint index = bandPixel.y * frame.imageSize.x + bandPixel.x;
    if (OUTPUT_MODE == OUTPUT_LINEAR_AND_CLASSES || OUTPUT_MODE == OUTPUT_LINEAR_CLASSES_AND_AOV) {
        pixels[index] = vec4(color, 1.0);
        classes[index] = uvec2(node, flags);
        if (OUTPUT_MODE == OUTPUT_LINEAR_CLASSES_AND_AOV) {
            writeAov(index, firstRay, firstHit);
        }
    } else {
        encodedPixels[index] = encode8(color);
    }
}
