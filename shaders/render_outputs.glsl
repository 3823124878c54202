// What a render writes, and which rows: the output buffers, the band of rows (push constants),
// the specialization constants every kernel takes (what to write, how many samples) and the
// workgroup's size (one invocation per pixel).
#ifndef HEXRAY_RENDER_OUTPUTS_GLSL
#define HEXRAY_RENDER_OUTPUTS_GLSL

#include "shader_interface.h"

layout(local_size_x = WORKGROUP_SIZE, local_size_y = WORKGROUP_SIZE) in;

layout(constant_id = OUTPUT_MODE_ID) const uint OUTPUT_MODE = OUTPUT_LINEAR_AND_CLASSES;
layout(constant_id = SAMPLES_PER_PIXEL_ID) const uint SAMPLES_PER_PIXEL = 1u;  // anti-aliasing

layout(std430, set = 0, binding = PIXEL_BINDING) writeonly buffer PixelBlock {
    vec4 pixels[];    // linear RGB of the rows of this band
};

// What each pixel shows: .x node index (BACKGROUND), .y flags (see shader_interface.h).
layout(std430, set = 0, binding = CLASS_BINDING) writeonly buffer ClassBlock {
    uvec2 classes[];
};

// The finished image, when that is all the host wants: RGBA8 packed in a uint, R lowest.
layout(std430, set = 0, binding = ENCODED_BINDING) writeonly buffer EncodedBlock {
    uint encodedPixels[];
};

// GpuBand: the rows, and (the data-driven kernel's light batches, light_batches.glsl) the samples
// of each pixel and the lights of each sample that this dispatch renders.
layout(push_constant) uniform BandBlock {
    uint firstRow;
    uint rowCount;
    uint firstTile;
    uint firstSample;
    uint endSample;
    uint firstLight;
    uint endLight;
    uint unused;
} band;

// The pixel of the band this invocation renders: one workgroup per WORKGROUP_SIZE^2 tile, all the
// band's tiles in a grid (taken in strips, below), or (a tile class's kernel, HEXRAY_TILE_LIST)
// the class's tiles, listed; or (f32-certified's f64 pass, HEXRAY_PIXEL_LIST) the pixels listed,
// one per invocation, in rows of the whole image (padding lies past its width), each written at
// its place in the list.
#if defined(HEXRAY_PIXEL_LIST)
layout(std430, set = 0, binding = TILE_BINDING) readonly buffer PixelListBlock {
    uvec2 listedPixels[];
};

uint listPlace() {
    return gl_WorkGroupID.x * (WORKGROUP_SIZE * WORKGROUP_SIZE) + gl_LocalInvocationIndex;
}

uvec2 bandPixel() {
    return listedPixels[listPlace()];
}
#elif defined(HEXRAY_TILE_LIST)
layout(std430, set = 0, binding = TILE_BINDING) readonly buffer TileBlock {
    uvec2 tiles[];  // (column, row) of tiles in the band
};

uvec2 bandPixel() {
    return tiles[band.firstTile + gl_WorkGroupID.x] * WORKGROUP_SIZE + gl_LocalInvocationID.xy;
}
#else
// Workgroups run in the order of their index. Each is given its tile so that they go through the
// image in strips STRIP_GROUPS tiles tall, column of tiles after column, rather than row of tiles
// after row: the data neighbouring rows' rays read (their lists and spheres) is then still
// cached when the next row reads it.
const uint STRIP_GROUPS = 16u;

uvec2 bandPixel() {
    uint columns = gl_NumWorkGroups.x;
    uint index = gl_WorkGroupID.y * columns + gl_WorkGroupID.x;
    uint strip = index / (columns * STRIP_GROUPS);
    uint stripRows = min(STRIP_GROUPS, gl_NumWorkGroups.y - strip * STRIP_GROUPS);  // the last may be short
    uint inStrip = index - strip * columns * STRIP_GROUPS;
    uvec2 group = uvec2(inStrip / stripRows, strip * STRIP_GROUPS + inStrip % stripRows);
    return group * WORKGROUP_SIZE + gl_LocalInvocationID.xy;
}
#endif

#endif  // HEXRAY_RENDER_OUTPUTS_GLSL
