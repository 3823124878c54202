// The entry point every kernel shares: one invocation per pixel averages its samples, and
// writes what OUTPUT_MODE asks for. A kernel defines, before including this file, how a ray
// finds its nearest hit and how a hit is shaded: the data-driven loops of render.comp, or the
// code hexray generates for one scene (host/kernels/kernel_generator.h).
#ifndef HEXRAY_KERNEL_MAIN_GLSL
#define HEXRAY_KERNEL_MAIN_GLSL

#include "camera_ray.glsl"
#include "encode.glsl"
#include "inspect_hooks.glsl"
#include "precision.glsl"
#include "ray.glsl"
#include "render_outputs.glsl"
#include "scene_data.glsl"
#include "surface.glsl"

#ifdef HEXRAY_LIGHT_BATCHES
#include "light_batches.glsl"
#else
// A generated kernel renders every sample and light of a pixel in one dispatch: its loops are
// unrolled.
#define FIRST_SAMPLE 0u
#define END_SAMPLE SAMPLES_PER_PIXEL
#define LAST_LIGHTS true
#endif

// The background colour: a generated kernel has it as a specialization constant, and then a tile
// of sky compiles to a constant store.
#ifndef SCENE_BACKGROUND
#define SCENE_BACKGROUND frame.background.rgb
#endif

// Whether a decision of the pixel is in doubt (certified.glsl): the host then renders it again in
// f64. A pixel says so in its alpha (0 for 1), a trace in its result's .w.
#ifdef HEXRAY_CERTIFIED
#define PIXEL_IN_DOUBT pixelInDoubt
#else
#define PIXEL_IN_DOUBT false
#endif

Hit findNearestHit(Ray ray);
// The colour of a hit and its pixel-class flags (ODD_CHECKER_BIT, a bit per lit light).
vec3 shade(Ray ray, Hit hit, out uint flags);
// Where the hit is and which way it faces, for any node (inspection only).
Surface hitSurface(Ray ray, Hit hit);
// Node `node`'s distance along a camera ray, NO_HIT for a miss (inspection only).
real candidateDistance(Ray ray, uint node);

// What the AOV buffer holds for the pixel's first sample.
void writeAov(uint index, Ray ray, Hit hit) {
    if (hit.node == NO_NODE) {
        aovs[index] = vec4(0.0);
        return;
    }
    aovs[index] = vec4(vec3(hitSurface(ray, hit).normal), float(hit.t));
}

// One invocation replays the requested pixel as main() renders it, recording every node's
// candidate t, the hit it chose, and, through the hooks called while shading, the surface and
// each light's terms for the requested sample.
// The pixel's colour from the sum of its samples: several saturated samples (each up to float's
// limit) would sum to inf.
vec3 sampleAverage(vec3 sum) {
    return min(sum, vec3(FLOAT_MAX)) / float(SAMPLES_PER_PIXEL);
}

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
            traceSurface(hitSurface(ray, hit), lookColor1(nodeLook(hit.node)));
        }
        uint flags = 0u;
        vec3 color = hit.node == NO_NODE ? SCENE_BACKGROUND : shade(ray, hit, flags);
        sum += color;
        if (traceActive) {
            trace.header.rayOrigin.xyz = ray.origin;
            trace.header.rayDirection.xyz = ray.direction;
            trace.header.hitPosition.w = hit.t;
            trace.header.result.yz = uvec2(hit.node, flags);
            trace.header.sampleColor = vec4(color, 1.0);
            for (uint i = 0u; i < frame.nodeCount; ++i) {
                trace.entries[i].values = vec4r(candidateDistance(ray, i), 0.0, 0.0, 0.0);
                trace.entries[i].status = uvec4(nodeGeometryKind(i), 0u, 0u, 0u);
            }
        }
    }
    traceActive = false;
    trace.header.pixelColor = vec4(sampleAverage(sum), 1.0);
    trace.header.result.w = PIXEL_IN_DOUBT ? 1u : 0u;
    trace.header.result.x = 1u;
}

#ifndef HEXRAY_LIGHT_BATCHES
// A generated kernel shades a sample whole and carries nothing.
vec3 shadeSample(Ray ray, Hit hit, bool background, uint index, out uint flags) {
    return shade(ray, hit, flags);
}

vec3 carriedSum(uint index) {
    return vec3(0.0);
}

void carrySum(uint index, vec3 sum) {}
#endif

// What the pixel shows and, with the AOVs, where: from its first sample.
void writeClass(uint index, uint node, uint flags, Ray firstRay, Hit firstHit) {
    if (OUTPUT_MODE == OUTPUT_LINEAR_AND_CLASSES || OUTPUT_MODE == OUTPUT_LINEAR_CLASSES_AND_AOV) {
        classes[index] = uvec2(node, flags);
        if (OUTPUT_MODE == OUTPUT_LINEAR_CLASSES_AND_AOV) {
            writeAov(index, firstRay, firstHit);
        }
    }
}

void writeColor(uint index, vec3 color) {
    if (OUTPUT_MODE == OUTPUT_LINEAR_AND_CLASSES || OUTPUT_MODE == OUTPUT_LINEAR_CLASSES_AND_AOV) {
        pixels[index] = vec4(color, PIXEL_IN_DOUBT ? 0.0 : 1.0);
    } else {
        encodedPixels[index] = encode8(color) & (PIXEL_IN_DOUBT ? ~ENCODED_ALPHA_BITS : 0xffffffffu);
    }
}

// Where the pixel's results go: its place in the band, or in the list of pixels it came from.
uint outputIndex(uvec2 pixel) {
#ifdef HEXRAY_PIXEL_LIST
    return listPlace();
#else
    return pixel.y * frame.imageSize.x + pixel.x;
#endif
}

void main() {
#ifdef HEXRAY_SCENE_VALUES_IN_BUFFER
    loadSceneValues();  // once: a use of each would be a load in every lane
#endif
    if (OUTPUT_MODE == OUTPUT_TRACE) {
        traceMain();
        return;
    }
    uvec2 pixel = bandPixel();
    if (pixel.x >= frame.imageSize.x || pixel.y >= band.rowCount) {
        return;
    }
    uint index = outputIndex(pixel);
    // The pixel is classified by its first sample (as the CPU reference does).
    uint node = NO_NODE;
    uint flags = 0u;
    Ray firstRay;
    Hit firstHit;
    vec3 sum = FIRST_SAMPLE == 0u ? vec3(0.0) : carriedSum(index);
    for (uint sampleIndex = FIRST_SAMPLE; sampleIndex < END_SAMPLE; ++sampleIndex) {
        Ray ray = primaryRay(uvec2(pixel.x, band.firstRow + pixel.y), sampleIndex);
        Hit hit = findNearestHit(ray);
        bool background = hit.node == NO_NODE;
        uint sampleFlags = 0u;
        // Shaded whatever the hit: lavapipe runs both sides of a branch anyway, and a select
        // costs it less than the branch's bookkeeping.
        vec3 shaded = shadeSample(ray, hit, background, index, sampleFlags);
        sum += background ? SCENE_BACKGROUND : shaded;
        if (sampleIndex == 0u) {
            node = hit.node;
            flags = background ? 0u : sampleFlags;
            firstRay = ray;
            firstHit = hit;
        }
    }
    if (!LAST_LIGHTS) {
        return;  // the sample goes on in the next dispatch
    }
    if (FIRST_SAMPLE == 0u) {
        writeClass(index, node, flags, firstRay, firstHit);
    }
    if (END_SAMPLE == SAMPLES_PER_PIXEL) {
        writeColor(index, sampleAverage(sum));
    } else {
        carrySum(index, sum);
    }
}

#endif  // HEXRAY_KERNEL_MAIN_GLSL
