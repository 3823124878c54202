#pragma once
// The scene as the shader reads it: C++ mirrors of the blocks in shaders/scene_data.glsl and the
// output blocks. tests/layout/gpu_layout_test.cpp compares every member's offset and every array's
// stride with glslang's reflection of the GLSL; the candidate lists' texels, which GLSL reads by
// index rather than as blocks, are pinned here.
//
// Positions are stored in the shader's precision, `Real` (float for the f32 variants, double
// for f64); colours are always float. In std430 a vec4 of doubles is 32-byte aligned, which
// C++ does not do by itself: RealVec4 carries that alignment.

#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shader_interface.h"  // the constants both sides agree on

namespace hexray::inline gpu {

template <typename Real>
struct alignas(4 * sizeof(Real)) RealVec4 : glm::vec<4, Real> {
    using glm::vec<4, Real>::vec;
    RealVec4() : glm::vec<4, Real>(0) {}
    RealVec4(const glm::vec<4, Real>& v) : glm::vec<4, Real>(v) {}
};

template <typename Real>
struct GpuFrame {
    RealVec4<Real> origin;        // .xyz: the eye; 0 when the scene is uploaded camera-relative
    RealVec4<Real> sheetTopLeft;  // .xyz: the pixel sheet, see camera.h
    RealVec4<Real> sheetRight;
    RealVec4<Real> sheetDown;
    glm::vec4 background;  // .rgb
    glm::vec4 ambient;     // .rgb
    glm::uvec2 imageSize;
    float samplingOffset;  // 0.5: pixel centres; 0: the course's pixel corners
    std::uint32_t nodeCount;
    std::uint32_t lightCount;
    // Of the nodes: a candidate kernel's planes are the first entries of its lists (candidates.glsl).
    std::uint32_t planeCount;
};

// A node: its geometry and the index of its look. The looks follow the nodes in the node buffer.
template <typename Real>
struct GpuNode {
    RealVec4<Real> geometry;  // plane: .x = height; sphere: .xyz = centre, .w = radius
    // Sphere: |eye - centre|^2 - r^2, the eye's power with respect to the sphere, which every
    // camera ray needs and float cannot form when the eye is close to a large sphere; planes: 0.
    Real eyePower;
    std::uint32_t geometryKind;  // GEOMETRY_*
    std::uint32_t look;          // its entry in the looks
};

// A shader as one kind of geometry shows it: every node of that shader and kind shares it, so a
// million spheres of a few shaders carry a few looks, not a million copies of their colours.
template <typename Real>
struct GpuLook {
    // Checker: .x = square size; on a plane .yz = the eye's fractional cell position (x, z) / size
    // (the integer part is folded into .w), .w = parity (0 or 1) of the eye's whole cells.
    RealVec4<Real> checker;
    glm::vec3 color1;          // constant / lambert colour, checker's first colour
    std::uint32_t shaderKind;  // SHADER_*: in color1's texel, read with it
    glm::vec4 color2;          // .rgb: checker's second colour
};

template <typename Real>
struct GpuLight {
    RealVec4<Real> position;  // .xyz; .w 1 when a sphere hides it from every visible point (isLightHiddenFromView)
    // .rgb = colour * intensity / scale^2: in the kernel's arithmetic, as the squared distances it
    // is divided by, since in f64 it can lie far outside float's range. .w 1 when no plane may
    // shadow a point the camera sees from it (render_plan.h's planeMayShadow).
    RealVec4<Real> power;
};

// Candidate lists (shaders/candidates.glsl), read as texels of 16 bytes: the grid buffer starts
// with the camera's axes, then one grid per view (the camera's, then CUBE_FACES per light). Always
// float: the shader looks its cell up in float whatever its precision.
struct GpuCandidateAxes {
    glm::vec4 right;    // .xyz
    glm::vec4 down;     // .xyz
    glm::vec4 forward;  // .xyz
};

struct GpuCandidateGrid {
    glm::vec4 window;  // .xy: tangent coordinates (u, v) of the first corner; .zw: cells per unit
    glm::uvec4 cells;  // .xy: cells across u and v; .z: the grid's first cell; .w: the cell past reach
    glm::vec4 reach;   // .x: the longest ray the lists hold (+inf: any); .y: 1 when they are in depth order
};

// The sphere records of the candidate lists, one per sphere, in two arrays one after the other in
// one buffer: every record's geometry (a RealVec4: centre, radius, the node's), then every record's
// GpuCandidateSphereNode. A shadow ray reads the geometry alone, which then fills its cache lines.
template <typename Real>
struct alignas(16) GpuCandidateSphereNode {
    Real eyePower;  // the node's eyePower
    std::uint32_t node;
    std::uint32_t look;  // the node's look: shading reads the hit's record, not its node
};

// One record's bytes, both parts: texels have no alignment beyond their own size, so two texels in
// float (the last word unused), three in double.
template <typename Real>
inline constexpr std::size_t kCandidateSphereBytes = sizeof(RealVec4<Real>) + sizeof(GpuCandidateSphereNode<Real>);

// Which rows of the image one dispatch covers (large images render in bands) and, of each pixel,
// which samples and, of each, which lights (the data-driven kernel's light batches,
// shaders/light_batches.glsl; a generated kernel renders them all): push constants.
struct GpuBand {
    std::uint32_t firstRow;
    std::uint32_t rowCount;
    std::uint32_t firstTile;  // a tile class's kernel: where its tiles start in the tile buffer
    std::uint32_t firstSample;
    std::uint32_t endSample;
    std::uint32_t firstLight;
    std::uint32_t endLight;
    std::uint32_t unused;
};

// What a pixel has so far, between the dispatches of a render in light batches.
struct GpuPixelCarry {
    glm::vec3 sum;  // the colours of its samples so far
    std::uint32_t flags;
    glm::vec3 irradiance;  // of the sample in progress
    std::uint32_t unused;
};

// One output pixel: linear RGB in .rgb, .a unused.
using GpuPixel = glm::vec4;

// One output classification: PixelClass's node and flags (see image/pixel_class.h).
using GpuPixelClass = glm::uvec2;

// One encoded output pixel: RGBA8, R in the lowest byte.
using GpuEncodedPixel = std::uint32_t;

// The specialization constants every kernel takes (shaders/render_outputs.glsl), in id order.
struct Specialization {
    std::uint32_t outputMode = OUTPUT_LINEAR_AND_CLASSES;  // OUTPUT_MODE_ID
    std::uint32_t samplesPerPixel = 1;                     // SAMPLES_PER_PIXEL_ID
    std::uint32_t lightBatches = 0;                        // LIGHT_BATCHES_ID (a VkBool32)
    std::uint32_t fastCameraTests = 0;                     // FAST_CAMERA_TESTS_ID (a VkBool32)
    std::uint32_t fastShadowTests = 0;                     // FAST_SHADOW_TESTS_ID (a VkBool32)

    auto operator<=>(const Specialization&) const = default;
};
static_assert(offsetof(Specialization, outputMode) == OUTPUT_MODE_ID * sizeof(std::uint32_t));
static_assert(offsetof(Specialization, samplesPerPixel) == SAMPLES_PER_PIXEL_ID * sizeof(std::uint32_t));
static_assert(offsetof(Specialization, lightBatches) == LIGHT_BATCHES_ID * sizeof(std::uint32_t));
static_assert(offsetof(Specialization, fastCameraTests) == FAST_CAMERA_TESTS_ID * sizeof(std::uint32_t));
static_assert(offsetof(Specialization, fastShadowTests) == FAST_SHADOW_TESTS_ID * sizeof(std::uint32_t));
static_assert(sizeof(Specialization) == FIRST_SCENE_CONSTANT_ID * sizeof(std::uint32_t));

// --- The candidate lists' texels (16 bytes each)
// scene_data.glsl reads nodes and lights as 16-byte texels, each member from its texel
// (shader_interface.h's NODE_*_TEXEL_*) on.
inline constexpr std::size_t kTexelBytes = 16;  // an RGBA32UI texel
template <typename Real>
constexpr bool nodeTexelsMatch(std::size_t eyePowerTexel, std::size_t texels) {
    using Node = GpuNode<Real>;
    return offsetof(Node, geometry) == NODE_GEOMETRY_TEXEL * kTexelBytes &&
           offsetof(Node, eyePower) == eyePowerTexel * kTexelBytes &&
           offsetof(Node, geometryKind) == eyePowerTexel * kTexelBytes + sizeof(Real) &&
           offsetof(Node, look) == offsetof(Node, geometryKind) + 4 && sizeof(Node) == texels * kTexelBytes;
}
static_assert(nodeTexelsMatch<float>(NODE_EYE_POWER_TEXEL_F32, NODE_TEXELS_F32) &&
              nodeTexelsMatch<double>(NODE_EYE_POWER_TEXEL_F64, NODE_TEXELS_F64));
template <typename Real>
constexpr bool lookTexelsMatch(std::size_t color1Texel, std::size_t color2Texel, std::size_t texels) {
    using Look = GpuLook<Real>;
    return offsetof(Look, checker) == LOOK_CHECKER_TEXEL * kTexelBytes &&
           offsetof(Look, color1) == color1Texel * kTexelBytes &&
           offsetof(Look, shaderKind) == color1Texel * kTexelBytes + 12 &&
           offsetof(Look, color2) == color2Texel * kTexelBytes && sizeof(Look) == texels * kTexelBytes;
}
static_assert(lookTexelsMatch<float>(LOOK_COLOR1_TEXEL_F32, LOOK_COLOR2_TEXEL_F32, LOOK_TEXELS_F32) &&
              lookTexelsMatch<double>(LOOK_COLOR1_TEXEL_F64, LOOK_COLOR2_TEXEL_F64, LOOK_TEXELS_F64));
static_assert(offsetof(GpuLight<float>, power) == 1 * 16 && offsetof(GpuLight<double>, power) == 2 * 16);
static_assert(sizeof(GpuLight<float>) == 2 * 16 && sizeof(GpuLight<double>) == 4 * 16);
static_assert(sizeof(GpuCandidateAxes) == 48);
static_assert(offsetof(GpuCandidateGrid, cells) == 16);
static_assert(offsetof(GpuCandidateGrid, reach) == 32);
static_assert(sizeof(GpuCandidateGrid) == 48);
static_assert(offsetof(GpuCandidateSphereNode<float>, node) == 4);
static_assert(offsetof(GpuCandidateSphereNode<float>, look) == 8);
static_assert(sizeof(GpuCandidateSphereNode<float>) == 16);
static_assert(offsetof(GpuCandidateSphereNode<double>, node) == 8);
static_assert(offsetof(GpuCandidateSphereNode<double>, look) == 12);
static_assert(sizeof(GpuCandidateSphereNode<double>) == 16);
static_assert(kCandidateSphereBytes<float> == 32 && kCandidateSphereBytes<double> == 48);

// --- Inspection (shaders/inspect_hooks.glsl): `hexray render --aov` and `hexray pixel`.

// One AOV pixel, from the pixel's first sample: .xyz the shading normal (facing the ray), .w the
// hit's t in the shader's units (camera-relative placement: world distance / placementScale).
// Both 0 for the background; the node and lit lights are in the classes buffer.
using GpuAovPixel = glm::vec4;

// The trace buffer's fixed part. The host writes `request`; the shader fills the rest for that
// pixel and sample, in its own units (see GpuAovPixel).
template <typename Real>
struct GpuTraceHeader {
    glm::uvec4 request;           // .x, .y pixel; .z the sample to trace
    glm::uvec4 result;            // .x 1 once written, .y hit node (0xffffffff: none), .z class flags, .w in doubt
    RealVec4<Real> rayOrigin;     // .xyz
    RealVec4<Real> rayDirection;  // .xyz, unit length
    RealVec4<Real> hitPosition;   // .xyz, .w = t
    RealVec4<Real> hitNormal;     // .xyz shading normal (lit shaders only)
    RealVec4<Real> shadowOrigin;  // .xyz where shadow rays start (lit shaders only)
    glm::vec4 albedo;             // .rgb (lit shaders only)
    glm::vec4 sampleColor;        // .rgb the traced sample's linear colour
    glm::vec4 pixelColor;         // .rgb the pixel's linear colour (average of its samples)
};

// Then one entry per node (the candidates: values.x = t, or REAL_MAX for a miss) and one per
// light (values = cos theta, r^2, shadow ray length; color.rgb = contribution; status.x a
// TRACE_LIGHT_* status).
template <typename Real>
struct GpuTraceEntry {
    RealVec4<Real> values;
    glm::vec4 color;
    glm::uvec4 status;
};

}  // namespace hexray::gpu
