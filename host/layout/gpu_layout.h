#pragma once
// The scene as the shader reads it: C++ mirrors of the std430 blocks in shaders/scene_data.glsl.
// Every offset is pinned by a static_assert so that a change on one side cannot drift silently.
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

namespace hexray::gpu {

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
};

// A node carries its own copy of its shader's parameters: one fetch per candidate, no indirection.
template <typename Real>
struct GpuNode {
    glm::uvec4 kinds;         // .x GEOMETRY_*, .y SHADER_*
    RealVec4<Real> geometry;  // plane: .x = height; sphere: .xyz = centre, .w = radius
    // Sphere: .x = |eye - centre|^2 - r^2, the eye's power with respect to the sphere, which
    // every camera ray needs and float cannot form when the eye is close to a large sphere.
    RealVec4<Real> surface;
    glm::vec4 color1;         // .rgb: constant / lambert colour, checker's first colour
    glm::vec4 color2;         // .rgb: checker's second colour
    // Checker: .x = square size; .yz = the eye's fractional cell position (x, z) / size on a
    // plane (the integer part is folded into .w), .w = parity (0 or 1) of the eye's whole cells.
    RealVec4<Real> checker;
};

template <typename Real>
struct GpuLight {
    RealVec4<Real> position;  // .xyz; .w 1 when a sphere hides it from every visible point (isLightHiddenFromView)
    // .rgb = colour * intensity / scale^2: in the kernel's arithmetic, as the squared distances it
    // is divided by, since in f64 it can lie far outside float's range.
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
    glm::vec4 reach;   // .x: the longest ray the lists hold (+inf: any)
};

// One sphere of a candidate list, packed tight (texels have no alignment beyond their own size):
// two texels in float, three in double.
template <typename Real>
struct GpuCandidateSphere {
    glm::vec<4, Real> sphere;  // centre, radius: the node's geometry
    Real eyePower;             // the node's surface.x
    std::uint32_t node;
    std::uint32_t unused[sizeof(Real) == 4 ? 2 : 1];
};

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
    std::uint32_t samplesPerPixel = 1;                      // SAMPLES_PER_PIXEL_ID

    auto operator<=>(const Specialization&) const = default;
};
static_assert(offsetof(Specialization, outputMode) == OUTPUT_MODE_ID * sizeof(std::uint32_t));
static_assert(offsetof(Specialization, samplesPerPixel) == SAMPLES_PER_PIXEL_ID * sizeof(std::uint32_t));

// --- std430 offsets, float variant
static_assert(offsetof(GpuFrame<float>, origin) == 0);
static_assert(offsetof(GpuFrame<float>, sheetTopLeft) == 16);
static_assert(offsetof(GpuFrame<float>, sheetRight) == 32);
static_assert(offsetof(GpuFrame<float>, sheetDown) == 48);
static_assert(offsetof(GpuFrame<float>, background) == 64);
static_assert(offsetof(GpuFrame<float>, ambient) == 80);
static_assert(offsetof(GpuFrame<float>, imageSize) == 96);
static_assert(offsetof(GpuFrame<float>, samplingOffset) == 104);
static_assert(offsetof(GpuFrame<float>, nodeCount) == 108);
static_assert(offsetof(GpuFrame<float>, lightCount) == 112);
static_assert(sizeof(GpuFrame<float>) == 128);
static_assert(offsetof(GpuNode<float>, kinds) == 0);
static_assert(offsetof(GpuNode<float>, geometry) == 16);
static_assert(offsetof(GpuNode<float>, surface) == 32);
static_assert(offsetof(GpuNode<float>, color1) == 48);
static_assert(offsetof(GpuNode<float>, color2) == 64);
static_assert(offsetof(GpuNode<float>, checker) == 80);
static_assert(sizeof(GpuNode<float>) == 96);
static_assert(offsetof(GpuLight<float>, position) == 0);
static_assert(offsetof(GpuLight<float>, power) == 16);
static_assert(sizeof(GpuLight<float>) == 32);
static_assert(sizeof(GpuCandidateAxes) == 48);
static_assert(offsetof(GpuCandidateGrid, cells) == 16);
static_assert(offsetof(GpuCandidateGrid, reach) == 32);
static_assert(sizeof(GpuCandidateGrid) == 48);
static_assert(offsetof(GpuCandidateSphere<float>, eyePower) == 16);
static_assert(offsetof(GpuCandidateSphere<float>, node) == 20);
static_assert(sizeof(GpuCandidateSphere<float>) == 32);

// --- std430 offsets, double variant (dvec4 aligned to 32)
static_assert(offsetof(GpuFrame<double>, origin) == 0);
static_assert(offsetof(GpuFrame<double>, sheetTopLeft) == 32);
static_assert(offsetof(GpuFrame<double>, sheetRight) == 64);
static_assert(offsetof(GpuFrame<double>, sheetDown) == 96);
static_assert(offsetof(GpuFrame<double>, background) == 128);
static_assert(offsetof(GpuFrame<double>, ambient) == 144);
static_assert(offsetof(GpuFrame<double>, imageSize) == 160);
static_assert(offsetof(GpuFrame<double>, samplingOffset) == 168);
static_assert(offsetof(GpuFrame<double>, nodeCount) == 172);
static_assert(offsetof(GpuFrame<double>, lightCount) == 176);
static_assert(sizeof(GpuFrame<double>) == 192);
static_assert(offsetof(GpuNode<double>, kinds) == 0);
static_assert(offsetof(GpuNode<double>, geometry) == 32);
static_assert(offsetof(GpuNode<double>, surface) == 64);
static_assert(offsetof(GpuNode<double>, color1) == 96);
static_assert(offsetof(GpuNode<double>, color2) == 112);
static_assert(offsetof(GpuNode<double>, checker) == 128);
static_assert(sizeof(GpuNode<double>) == 160);
static_assert(offsetof(GpuLight<double>, position) == 0);
static_assert(offsetof(GpuLight<double>, power) == 32);
static_assert(sizeof(GpuLight<double>) == 64);

// --- Inspection (shaders/inspect_hooks.glsl): `hexray render --aov` and `hexray pixel`.

// One AOV pixel, from the pixel's first sample: .xyz the shading normal (facing the ray), .w the
// hit's t in the shader's units (camera-relative placement: world distance / placementScale).
// Both 0 for the background; the node and lit lights are in the classes buffer.
using GpuAovPixel = glm::vec4;

// The trace buffer's fixed part. The host writes `request`; the shader fills the rest for that
// pixel and sample, in its own units (see GpuAovPixel).
template <typename Real>
struct GpuTraceHeader {
    glm::uvec4 request;             // .x, .y pixel; .z the sample to trace
    glm::uvec4 result;              // .x 1 once written, .y hit node (0xffffffff: none), .z class flags
    RealVec4<Real> rayOrigin;       // .xyz
    RealVec4<Real> rayDirection;    // .xyz, unit length
    RealVec4<Real> hitPosition;     // .xyz, .w = t
    RealVec4<Real> hitNormal;       // .xyz shading normal (lit shaders only)
    RealVec4<Real> shadowOrigin;    // .xyz where shadow rays start (lit shaders only)
    glm::vec4 albedo;               // .rgb (lit shaders only)
    glm::vec4 sampleColor;          // .rgb the traced sample's linear colour
    glm::vec4 pixelColor;           // .rgb the pixel's linear colour (average of its samples)
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

static_assert(sizeof(GpuAovPixel) == 16);
static_assert(offsetof(GpuTraceHeader<float>, request) == 0);
static_assert(offsetof(GpuTraceHeader<float>, result) == 16);
static_assert(offsetof(GpuTraceHeader<float>, rayOrigin) == 32);
static_assert(offsetof(GpuTraceHeader<float>, rayDirection) == 48);
static_assert(offsetof(GpuTraceHeader<float>, hitPosition) == 64);
static_assert(offsetof(GpuTraceHeader<float>, hitNormal) == 80);
static_assert(offsetof(GpuTraceHeader<float>, shadowOrigin) == 96);
static_assert(offsetof(GpuTraceHeader<float>, albedo) == 112);
static_assert(offsetof(GpuTraceHeader<float>, sampleColor) == 128);
static_assert(offsetof(GpuTraceHeader<float>, pixelColor) == 144);
static_assert(sizeof(GpuTraceHeader<float>) == 160);
static_assert(offsetof(GpuTraceEntry<float>, values) == 0);
static_assert(offsetof(GpuTraceEntry<float>, color) == 16);
static_assert(offsetof(GpuTraceEntry<float>, status) == 32);
static_assert(sizeof(GpuTraceEntry<float>) == 48);
static_assert(offsetof(GpuTraceHeader<double>, request) == 0);
static_assert(offsetof(GpuTraceHeader<double>, result) == 16);
static_assert(offsetof(GpuTraceHeader<double>, rayOrigin) == 32);
static_assert(offsetof(GpuTraceHeader<double>, rayDirection) == 64);
static_assert(offsetof(GpuTraceHeader<double>, hitPosition) == 96);
static_assert(offsetof(GpuTraceHeader<double>, hitNormal) == 128);
static_assert(offsetof(GpuTraceHeader<double>, shadowOrigin) == 160);
static_assert(offsetof(GpuTraceHeader<double>, albedo) == 192);
static_assert(offsetof(GpuTraceHeader<double>, sampleColor) == 208);
static_assert(offsetof(GpuTraceHeader<double>, pixelColor) == 224);
static_assert(offsetof(GpuCandidateSphere<double>, eyePower) == 32);
static_assert(offsetof(GpuCandidateSphere<double>, node) == 40);
static_assert(sizeof(GpuCandidateSphere<double>) == 48);
static_assert(sizeof(GpuTraceHeader<double>) == 256);  // std430: the struct rounds up to its 32-byte alignment
static_assert(offsetof(GpuTraceEntry<double>, values) == 0);
static_assert(offsetof(GpuTraceEntry<double>, color) == 32);
static_assert(offsetof(GpuTraceEntry<double>, status) == 48);
static_assert(sizeof(GpuTraceEntry<double>) == 64);

static_assert(sizeof(GpuBand) == 32);
static_assert(offsetof(GpuPixelCarry, flags) == 12);
static_assert(offsetof(GpuPixelCarry, irradiance) == 16);
static_assert(sizeof(GpuPixelCarry) == 32);
static_assert(sizeof(GpuPixel) == 16);
static_assert(sizeof(GpuPixelClass) == 8);

}  // namespace hexray::gpu
