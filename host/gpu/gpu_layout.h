#pragma once
// The scene as the shader reads it: C++ mirrors of the std430 blocks in shaders/scene_data.glsl.
// Every offset is pinned by a static_assert so that a change on one side cannot drift silently.
//
// All positions are camera-relative (the host subtracts the eye position in double before
// converting to float), so large world coordinates cost the shader no precision.

#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace hexray::gpu {

// Local size of render.comp in x and y, passed as specialization constants 0 and 1.
inline constexpr std::uint32_t kWorkgroupSize = 8;

// Descriptor bindings of set 0.
inline constexpr std::uint32_t kFrameBinding = 0;
inline constexpr std::uint32_t kNodeBinding = 1;
inline constexpr std::uint32_t kLightBinding = 2;
inline constexpr std::uint32_t kPixelBinding = 3;

enum GeometryKind : std::uint32_t { kGeometryPlane = 0, kGeometrySphere = 1 };
enum ShaderKind : std::uint32_t { kShaderConstant = 0, kShaderLambert = 1, kShaderChecker = 2 };

struct GpuFrame {
    glm::vec4 sheetTopLeft;  // .xyz: the pixel sheet, see camera.h (the eye is the origin)
    glm::vec4 sheetRight;
    glm::vec4 sheetDown;
    glm::vec4 background;  // .rgb
    glm::vec4 ambient;     // .rgb
    glm::uvec2 imageSize;
    float samplingOffset;  // 0.5: pixel centres; 0: the course's pixel corners
    std::uint32_t nodeCount;
    std::uint32_t lightCount;
    std::uint32_t padding[3];
};
static_assert(offsetof(GpuFrame, sheetTopLeft) == 0);
static_assert(offsetof(GpuFrame, sheetRight) == 16);
static_assert(offsetof(GpuFrame, sheetDown) == 32);
static_assert(offsetof(GpuFrame, background) == 48);
static_assert(offsetof(GpuFrame, ambient) == 64);
static_assert(offsetof(GpuFrame, imageSize) == 80);
static_assert(offsetof(GpuFrame, samplingOffset) == 88);
static_assert(offsetof(GpuFrame, nodeCount) == 92);
static_assert(offsetof(GpuFrame, lightCount) == 96);
static_assert(sizeof(GpuFrame) == 112);

// A node carries its own copy of its shader's parameters: one fetch per candidate, no indirection.
struct GpuNode {
    glm::uvec4 kinds;     // .x GeometryKind, .y ShaderKind
    glm::vec4 geometry;   // plane: .x = height; sphere: .xyz = centre, .w = radius
    glm::vec4 color1;     // .rgb: constant / lambert colour, checker's first colour
    glm::vec4 color2;     // .rgb: checker's second colour
    // Checker: .x = square size; .yz = the eye's fractional cell position (x, z) / size on a
    // plane (the integer part is folded into .w), .w = parity (0 or 1) of the eye's whole cells.
    glm::vec4 checker;
};
static_assert(offsetof(GpuNode, kinds) == 0);
static_assert(offsetof(GpuNode, geometry) == 16);
static_assert(offsetof(GpuNode, color1) == 32);
static_assert(offsetof(GpuNode, color2) == 48);
static_assert(offsetof(GpuNode, checker) == 64);
static_assert(sizeof(GpuNode) == 80);

struct GpuLight {
    glm::vec4 position;  // .xyz
    glm::vec4 power;     // .rgb = colour * intensity
};
static_assert(offsetof(GpuLight, position) == 0);
static_assert(offsetof(GpuLight, power) == 16);
static_assert(sizeof(GpuLight) == 32);

// Which rows of the image one dispatch covers (large images render in bands).
struct GpuBand {
    std::uint32_t firstRow;
    std::uint32_t rowCount;
};
static_assert(sizeof(GpuBand) == 8);

// One output pixel: linear RGB in .rgb, .a unused.
using GpuPixel = glm::vec4;
static_assert(sizeof(GpuPixel) == 16);

}  // namespace hexray::gpu
