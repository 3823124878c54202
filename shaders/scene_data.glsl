// The scene as uploaded by the host. Mirrors host/layout/gpu_layout.h (std430, offsets asserted there).
// With the camera-relative placement the eye is the origin.
//
// Small scenes (HEXRAY_UNIFORM_SCENE: up to SMALL_SCENE_CAPACITY nodes and lights) come in
// uniform buffers, which lavapipe reads as values shared by the whole SIMD group when the index
// is a constant; larger ones in storage buffers. The structs are vec4-aligned, so the std140 and
// std430 layouts of these blocks are the same bytes.
#ifndef HEXRAY_SCENE_DATA_GLSL
#define HEXRAY_SCENE_DATA_GLSL

#include "shader_interface.h"
#include "precision.glsl"

#ifdef HEXRAY_UNIFORM_SCENE
#define SCENE_BLOCK(binding_) layout(std140, set = 0, binding = binding_) uniform
#define SCENE_ARRAY_LENGTH SMALL_SCENE_CAPACITY
#else
#define SCENE_BLOCK(binding_) layout(std430, set = 0, binding = binding_) readonly buffer
#define SCENE_ARRAY_LENGTH
#endif

SCENE_BLOCK(FRAME_BINDING) FrameBlock {
    vec4r origin;
    vec4r sheetTopLeft;
    vec4r sheetRight;
    vec4r sheetDown;
    vec4 background;
    vec4 ambient;
    uvec2 imageSize;
    float samplingOffset;
    uint nodeCount;
    uint lightCount;
} frame;

struct Node {
    uvec4 kinds;      // .x geometry, .y shader
    vec4r geometry;   // plane: .x height; sphere: .xyz centre, .w radius
    real eyePower;    // sphere: the eye's power |eye - centre|^2 - r^2 (from the host, in double); planes: 0
    real unused0;
    real unused1;
    real unused2;
    vec4 color1;
    vec4 color2;
    vec4r checker;    // .x size, .yz eye's fractional cell (plane), .w parity of the eye's cells
};
SCENE_BLOCK(NODE_BINDING) NodeBlock {
    Node nodes[SCENE_ARRAY_LENGTH];
};

struct Light {
    vec4r position;   // .w: 1 when a sphere holding the eye hides it from every visible point
    vec4r power;      // colour * intensity (in f64 beyond float's range)
};
SCENE_BLOCK(LIGHT_BINDING) LightBlock {
    Light lights[SCENE_ARRAY_LENGTH];
};

#endif  // HEXRAY_SCENE_DATA_GLSL
