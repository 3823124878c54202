// The scene as uploaded by the host. Mirrors host/gpu/gpu_layout.h (std430, offsets asserted there).
// With the camera-relative placement (every variant but f32-naive) the eye is the origin.
//
// Small scenes (HEXRAY_UNIFORM_SCENE: up to 32 nodes and 32 lights) come in uniform buffers,
// which lavapipe reads as values shared by the whole SIMD group (about 1.5x faster than
// storage buffers here); larger ones in storage buffers. The structs are vec4-aligned, so the
// std140 and std430 layouts of these blocks are the same bytes.
#ifdef HEXRAY_UNIFORM_SCENE
#define SCENE_BLOCK(binding_) layout(std140, set = 0, binding = binding_) uniform
#define SCENE_ARRAY_LENGTH 32
#else
#define SCENE_BLOCK(binding_) layout(std430, set = 0, binding = binding_) readonly buffer
#define SCENE_ARRAY_LENGTH
#endif

const uint GEOMETRY_PLANE = 0u;
const uint GEOMETRY_SPHERE = 1u;
const uint SHADER_CONSTANT = 0u;
const uint SHADER_LAMBERT = 1u;
const uint SHADER_CHECKER = 2u;

SCENE_BLOCK(0) FrameBlock {
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
    uint planeCount;  // BVH scenes: the first planeCount entries of primitiveNodes (bvh.glsl)
} frame;

struct Node {
    uvec4 kinds;      // .x geometry, .y shader
    vec4r geometry;   // plane: .x height; sphere: .xyz centre, .w radius
    vec4r surface;    // sphere: .x the eye's power |eye - centre|^2 - r^2 (from the host, in double)
    vec4 color1;
    vec4 color2;
    vec4r checker;    // .x size, .yz eye's fractional cell (plane), .w parity of the eye's cells
};
SCENE_BLOCK(1) NodeBlock {
    Node nodes[SCENE_ARRAY_LENGTH];
};

struct Light {
    vec4r position;
    vec4 power;       // colour * intensity
};
SCENE_BLOCK(2) LightBlock {
    Light lights[SCENE_ARRAY_LENGTH];
};

layout(std430, set = 0, binding = 3) writeonly buffer PixelBlock {
    vec4 pixels[];    // linear RGB of the rows of this band
};

// What each pixel shows: .x node index (0xffffffff: background), .y flags (see pixel_class.h).
layout(std430, set = 0, binding = 4) writeonly buffer ClassBlock {
    uvec2 classes[];
};
const uint BACKGROUND = 0xffffffffu;

// The finished image, when that is all the host wants: RGBA8 packed in a uint, R lowest.
layout(std430, set = 0, binding = 5) writeonly buffer EncodedBlock {
    uint encodedPixels[];
};
const uint ODD_CHECKER_BIT = 1u;
const uint CLASSIFIED_LIGHTS = 31u;

layout(push_constant) uniform BandBlock {
    uint firstRow;
    uint rowCount;
} band;
