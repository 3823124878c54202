// The scene as uploaded by the host. Mirrors host/gpu/gpu_layout.h (std430, offsets asserted there).
// Positions are camera-relative: the eye is at the origin.

const uint GEOMETRY_PLANE = 0u;
const uint GEOMETRY_SPHERE = 1u;
const uint SHADER_CONSTANT = 0u;
const uint SHADER_LAMBERT = 1u;
const uint SHADER_CHECKER = 2u;

layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {
    vec4 sheetTopLeft;
    vec4 sheetRight;
    vec4 sheetDown;
    vec4 background;
    vec4 ambient;
    uvec2 imageSize;
    float samplingOffset;
    uint nodeCount;
    uint lightCount;
} frame;

struct Node {
    uvec4 kinds;     // .x geometry, .y shader
    vec4 geometry;   // plane: .x height; sphere: .xyz centre, .w radius
    vec4 color1;
    vec4 color2;
    vec4 checker;    // .x size, .yz eye's fractional cell (plane), .w parity of the eye's cells
};
layout(std430, set = 0, binding = 1) readonly buffer NodeBlock {
    Node nodes[];
};

struct Light {
    vec4 position;
    vec4 power;      // colour * intensity
};
layout(std430, set = 0, binding = 2) readonly buffer LightBlock {
    Light lights[];
};

layout(std430, set = 0, binding = 3) writeonly buffer PixelBlock {
    vec4 pixels[];   // linear RGB of the rows of this band
};

layout(push_constant) uniform BandBlock {
    uint firstRow;
    uint rowCount;
} band;
