// Every constant the host (C++) and the shaders (GLSL) must agree on, read by both: the C++
// side includes this file from host/layout/gpu_layout.h and host/image/pixel_class.h, the GLSL
// side from the shader library. The std430 struct mirrors and their offset checks are C++
// only (host/layout/gpu_layout.h); their GLSL declarations are in scene_data.glsl.
#ifndef HEXRAY_SHADER_INTERFACE_H
#define HEXRAY_SHADER_INTERFACE_H

#ifdef __cplusplus
#include <cstdint>
namespace hexray::inline gpu {
using uint = std::uint32_t;
#define HEXRAY_CONSTANT inline constexpr
#else
#define HEXRAY_CONSTANT const
#endif

// Local size in x and y of every kernel: one invocation per pixel, WORKGROUP_SIZE² per group.
HEXRAY_CONSTANT uint WORKGROUP_SIZE = 8u;

// Descriptor bindings of set 0.
HEXRAY_CONSTANT uint FRAME_BINDING = 0u;
HEXRAY_CONSTANT uint NODE_BINDING = 1u;
HEXRAY_CONSTANT uint LIGHT_BINDING = 2u;
HEXRAY_CONSTANT uint PIXEL_BINDING = 3u;              // linear RGB
HEXRAY_CONSTANT uint CLASS_BINDING = 4u;              // what each pixel shows (node, flags)
HEXRAY_CONSTANT uint ENCODED_BINDING = 5u;            // the finished 8-bit image
HEXRAY_CONSTANT uint CANDIDATE_GRID_BINDING = 6u;     // candidate lists: the camera's and lights' grids
HEXRAY_CONSTANT uint CANDIDATE_CELL_BINDING = 7u;     // candidate lists: where each cell's list starts
HEXRAY_CONSTANT uint AOV_BINDING = 8u;                // inspection: per-pixel depth and normal
HEXRAY_CONSTANT uint TRACE_BINDING = 9u;              // inspection: one pixel explained
HEXRAY_CONSTANT uint TILE_BINDING = 10u;              // a tile class's kernel: the tiles it renders
HEXRAY_CONSTANT uint CANDIDATE_ENTRY_BINDING = 11u;   // candidate lists: the lists, one after another
HEXRAY_CONSTANT uint CANDIDATE_SPHERE_BINDING = 12u;  // candidate lists: the spheres they name
HEXRAY_CONSTANT uint CARRY_BINDING = 13u;             // light batches: what a pixel has so far, between dispatches
HEXRAY_CONSTANT uint SCENE_VALUE_BINDING = 14u;  // a generated kernel's scene values, when not specialization constants
HEXRAY_CONSTANT uint BINDING_COUNT = 15u;
// The candidate bindings are uniform texel buffers (RGBA32UI grids and spheres, R32UI cells and
// entries), and so are a larger scene's nodes and lights: lavapipe (Mesa 22.3) reads a texel buffer
// at a different index in each lane with vector loads or gathers, but a storage buffer one lane
// and one word at a time, each word inserted into its vector through the stack (a store-forwarding
// stall on AVX2: docs/performance.md, "The data-driven kernel on lavapipe").

// Node kinds (GpuNode::kinds.x and .y).
HEXRAY_CONSTANT uint GEOMETRY_PLANE = 0u;
HEXRAY_CONSTANT uint GEOMETRY_SPHERE = 1u;
HEXRAY_CONSTANT uint SHADER_CONSTANT = 0u;
HEXRAY_CONSTANT uint SHADER_LAMBERT = 1u;
HEXRAY_CONSTANT uint SHADER_CHECKER = 2u;

// What a render writes (specialization constant OUTPUT_MODE).
HEXRAY_CONSTANT uint OUTPUT_LINEAR_AND_CLASSES = 0u;      // pixels and classes
HEXRAY_CONSTANT uint OUTPUT_8BIT_LINEAR = 1u;             // the encoded image, no transfer function
HEXRAY_CONSTANT uint OUTPUT_8BIT_SRGB = 2u;               // the encoded image, sRGB
HEXRAY_CONSTANT uint OUTPUT_LINEAR_CLASSES_AND_AOV = 3u;  // pixels, classes and AOVs
HEXRAY_CONSTANT uint OUTPUT_TRACE = 4u;                   // one pixel explained into the trace buffer

// Specialization constant ids: every kernel's, then a generated kernel's scene values
// (host/kernels/scene_constants.h), one id per component from FIRST_SCENE_CONSTANT_ID on.
HEXRAY_CONSTANT uint OUTPUT_MODE_ID = 0u;
HEXRAY_CONSTANT uint SAMPLES_PER_PIXEL_ID = 1u;
HEXRAY_CONSTANT uint LIGHT_BATCHES_ID = 2u;      // the data-driven kernel: 1 when a band takes several dispatches
HEXRAY_CONSTANT uint FAST_CAMERA_TESTS_ID = 3u;  // the data-driven kernel: 1 when every sphere takes the fast test
HEXRAY_CONSTANT uint FAST_SHADOW_TESTS_ID = 4u;  // the same from every light
HEXRAY_CONSTANT uint FIRST_SCENE_CONSTANT_ID = 5u;

// What each pixel shows (PixelClass on the host): the node index, or BACKGROUND; flags with
// ODD_CHECKER_BIT for a checker-shaded hit in a color2 cell and bit i + 1 for each of the first
// CLASSIFIED_LIGHTS lights that reaches the point.
HEXRAY_CONSTANT uint BACKGROUND = 0xffffffffu;
// An encoded pixel's alpha byte: all ones, or (f32-certified) 0 for a pixel in doubt, as a linear
// pixel's alpha is 1 or 0 (kernel_main.glsl writeColor; GpuRenderer renders those again in f64).
HEXRAY_CONSTANT uint ENCODED_ALPHA_BITS = 0xff000000u;
HEXRAY_CONSTANT uint ODD_CHECKER_BIT = 1u;
HEXRAY_CONSTANT uint CLASSIFIED_LIGHTS = 31u;

// How the shader treated one light at a traced sample.
HEXRAY_CONSTANT uint TRACE_LIGHT_NOT_EVALUATED = 0u;  // background or a constant shader
HEXRAY_CONSTANT uint TRACE_LIGHT_LIT = 1u;
HEXRAY_CONSTANT uint TRACE_LIGHT_FACING_AWAY = 2u;  // cos theta <= 0
HEXRAY_CONSTANT uint TRACE_LIGHT_SHADOWED = 3u;
HEXRAY_CONSTANT uint TRACE_LIGHT_AT_POINT = 4u;  // r^2 = 0

// Where the data-driven kernels read a node's members and a look's (scene_data.glsl), in 16-byte
// texels from the start of its record, in f32 and in f64 (std430 puts a dvec4, two texels, at a
// multiple of 32 bytes); gpu_layout.h asserts them against GpuNode and GpuLook. A node's geometry
// kind and look are the words after its eyePower, in the same texel; a look's shader kind is the
// word after its first colour.
HEXRAY_CONSTANT uint NODE_GEOMETRY_TEXEL = 0u;
HEXRAY_CONSTANT uint NODE_EYE_POWER_TEXEL_F32 = 1u, NODE_EYE_POWER_TEXEL_F64 = 2u;
HEXRAY_CONSTANT uint NODE_TEXELS_F32 = 2u, NODE_TEXELS_F64 = 4u;
HEXRAY_CONSTANT uint LOOK_CHECKER_TEXEL = 0u;
HEXRAY_CONSTANT uint LOOK_COLOR1_TEXEL_F32 = 1u, LOOK_COLOR1_TEXEL_F64 = 2u;
HEXRAY_CONSTANT uint LOOK_COLOR2_TEXEL_F32 = 2u, LOOK_COLOR2_TEXEL_F64 = 3u;
HEXRAY_CONSTANT uint LOOK_TEXELS_F32 = 3u, LOOK_TEXELS_F64 = 4u;

// The uniform-buffer layout's capacity: scenes with at most this many nodes and as many lights
// come in uniform blocks of this many entries.
HEXRAY_CONSTANT uint SMALL_SCENE_CAPACITY = 32u;

// Candidate lists (host/accel/candidate_lists.h): cell 0 lists the planes, by node index, and every
// other cell spheres, by their rank among the scene's spheres (their record in the sphere buffer).
// Grid 0 is the camera's, then each light has one grid per face of a cube around it, face
// 2 * axis + (1 if the direction along that axis is negative).
HEXRAY_CONSTANT uint PLANE_CELL = 0u;
HEXRAY_CONSTANT uint CAMERA_GRID = 0u;
HEXRAY_CONSTANT uint CUBE_FACES = 6u;
// A grid's cells lie in bands of CELL_BAND_ROWS rows (the last band may have fewer), band after
// band, and within a band column after column: a cache line of cell starts then covers a square
// of cells, not a strip of one row, and the rays of neighbouring pixels share it and their lists.
HEXRAY_CONSTANT uint CELL_BAND_ROWS = 4u;
// A robust kernel's camera lists are in depth order from the eye: by |f| (1 - m) - r (1 + m) for
// a sphere of radius r whose centre lies f from it, m being DEPTH_ORDER_UNITS units of the
// kernel's roundoff, below any distance the kernel's own test of the sphere can report (its error
// is a few units of |f| + r). A ray stops reading its list at the first sphere whose depth passes
// its nearest hit so far by DEPTH_ORDER_SLACK of it, more than the kernel's rounding of that test
// and the depth's own rounding to float (candidates.glsl's liesBeyond). The lights' lists stay in
// record order: sorting them cost the host more than it saved the kernel.
HEXRAY_CONSTANT float DEPTH_ORDER_UNITS = 1024.0;
HEXRAY_CONSTANT float DEPTH_ORDER_SLACK = 1.52587890625e-5;  // 2^-16

// f32-naive's shadow rays start this far off the surface along its normal, as the course does: a
// no-op once below half an ulp of the coordinates, and too large for contact shadows near the
// origin. The candidate lists' reach for those rays counts it.
HEXRAY_CONSTANT float TEXTBOOK_SHADOW_NUDGE = 1e-4;

#undef HEXRAY_CONSTANT
#ifdef __cplusplus
}  // namespace hexray::gpu
#endif

#endif  // HEXRAY_SHADER_INTERFACE_H
