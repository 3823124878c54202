// The scene as uploaded by the host. Mirrors host/gpu/gpu_layout.h (std430, offsets asserted there).
// With the camera-relative placement (every variant but f32-naive) the eye is the origin.

const uint GEOMETRY_PLANE = 0u;
const uint GEOMETRY_SPHERE = 1u;
const uint SHADER_CONSTANT = 0u;
const uint SHADER_LAMBERT = 1u;
const uint SHADER_CHECKER = 2u;

layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {
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
    vec4r surface;    // sphere: .x the eye's power |eye - centre|^2 - r^2 (from the host, in double)
    vec4 color1;
    vec4 color2;
    vec4r checker;    // .x size, .yz eye's fractional cell (plane), .w parity of the eye's cells
};
layout(std430, set = 0, binding = 1) readonly buffer NodeBlock {
    Node nodes[];
};

struct Light {
    vec4r position;
    vec4 power;       // colour * intensity
};
layout(std430, set = 0, binding = 2) readonly buffer LightBlock {
    Light lights[];
};

layout(std430, set = 0, binding = 3) writeonly buffer PixelBlock {
    vec4 pixels[];    // linear RGB of the rows of this band
};

// What each pixel shows: .x node index (0xffffffff: background), .y flags (see pixel_class.h).
layout(std430, set = 0, binding = 4) writeonly buffer ClassBlock {
    uvec2 classes[];
};
const uint BACKGROUND = 0xffffffffu;
const uint ODD_CHECKER_BIT = 1u;
const uint CLASSIFIED_LIGHTS = 31u;

layout(push_constant) uniform BandBlock {
    uint firstRow;
    uint rowCount;
} band;
