// The scene as uploaded by the host. Mirrors host/layout/gpu_layout.h (offsets asserted there).
// With the camera-relative placement the eye is the origin.
//
// The frame is a uniform block: lavapipe reads it once for the whole SIMD group. Small scenes'
// nodes and lights (HEXRAY_UNIFORM_SCENE: up to SMALL_SCENE_CAPACITY of each) are uniform blocks
// too, which a generated kernel reads at constant indices; larger ones are uniform texel buffers
// of the same bytes (texels.glsl), read at each lane's own index. Read them through the
// accessors below, the same in both layouts.
#ifndef HEXRAY_SCENE_DATA_GLSL
#define HEXRAY_SCENE_DATA_GLSL

#include "shader_interface.h"
#include "precision.glsl"

layout(std140, set = 0, binding = FRAME_BINDING) uniform FrameBlock {
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
    uint planeCount;
} frame;

struct Node {
    vec4r geometry;   // plane: .x height; sphere: .xyz centre, .w radius
    real eyePower;    // sphere: the eye's power |eye - centre|^2 - r^2 (from the host, in double); planes: 0
    uint geometryKind;
    uint look;        // the node's entry in the looks
};

// A shader as one kind of geometry shows it, shared by every node of that shader and kind.
struct Look {
    vec4r checker;    // .x size, .yz eye's fractional cell (plane), .w parity of the eye's cells
    vec3 color1;
    uint shaderKind;  // in color1's texel
    vec4 color2;
};

struct Light {
    vec4r position;   // .w: 1 when a sphere holding the eye hides it from every visible point
    vec4r power;      // colour * intensity (in f64 beyond float's range)
};

#ifdef HEXRAY_UNIFORM_SCENE
layout(std140, set = 0, binding = NODE_BINDING) uniform NodeBlock {
    Node nodes[SMALL_SCENE_CAPACITY];
    Look looks[SMALL_SCENE_CAPACITY];  // a small scene has at most as many looks as nodes
};
layout(std140, set = 0, binding = LIGHT_BINDING) uniform LightBlock {
    Light lights[SMALL_SCENE_CAPACITY];
};

vec4r nodeGeometry(uint i) { return nodes[i].geometry; }
real nodeEyePower(uint i) { return nodes[i].eyePower; }
uint nodeGeometryKind(uint i) { return nodes[i].geometryKind; }
uint nodeLook(uint i) { return nodes[i].look; }
uint lookShaderKind(uint l) { return looks[l].shaderKind; }
vec3 lookColor1(uint l) { return looks[l].color1; }
vec3 lookColor2(uint l) { return looks[l].color2.rgb; }
vec4r lookChecker(uint l) { return looks[l].checker; }
vec4r lightPosition(uint i) { return lights[i].position; }
vec4r lightPower(uint i) { return lights[i].power; }
#else
#include "texels.glsl"

// The nodes' records, then the looks'.
layout(set = 0, binding = NODE_BINDING) uniform usamplerBuffer nodeTexels;
layout(set = 0, binding = LIGHT_BINDING) uniform usamplerBuffer lightTexels;

// Where Node's and Look's members start, in texels from the start of their record (shader_interface.h).
#ifdef HEXRAY_F64
const int NODE_EYE_POWER_TEXEL = int(NODE_EYE_POWER_TEXEL_F64), NODE_TEXELS = int(NODE_TEXELS_F64),
          LOOK_COLOR1_TEXEL = int(LOOK_COLOR1_TEXEL_F64), LOOK_COLOR2_TEXEL = int(LOOK_COLOR2_TEXEL_F64),
          LOOK_TEXELS = int(LOOK_TEXELS_F64);
#else
const int NODE_EYE_POWER_TEXEL = int(NODE_EYE_POWER_TEXEL_F32), NODE_TEXELS = int(NODE_TEXELS_F32),
          LOOK_COLOR1_TEXEL = int(LOOK_COLOR1_TEXEL_F32), LOOK_COLOR2_TEXEL = int(LOOK_COLOR2_TEXEL_F32),
          LOOK_TEXELS = int(LOOK_TEXELS_F32);
#endif
const int LIGHT_TEXELS = 2 * REAL_VEC4_TEXELS;

int nodeTexel(uint i, int member) { return NODE_TEXELS * int(i) + member; }
int lookTexel(uint l, int member) { return NODE_TEXELS * int(frame.nodeCount) + LOOK_TEXELS * int(l) + member; }

vec4r nodeGeometry(uint i) { return realVec4At(nodeTexels, nodeTexel(i, int(NODE_GEOMETRY_TEXEL))); }
real nodeEyePower(uint i) {
    uint unused;
    return realAt(nodeTexels, nodeTexel(i, NODE_EYE_POWER_TEXEL), unused);
}
// The geometry kind and the look: the two words after eyePower.
uvec2 nodeKindAndLook(uint i) {
    uvec4 texel = texelFetch(nodeTexels, nodeTexel(i, NODE_EYE_POWER_TEXEL));
#ifdef HEXRAY_F64
    return texel.zw;
#else
    return texel.yz;
#endif
}
uint nodeGeometryKind(uint i) { return nodeKindAndLook(i).x; }
uint nodeLook(uint i) { return nodeKindAndLook(i).y; }
// The first colour and the shader kind share a texel.
uint lookShaderKind(uint l) { return texelFetch(nodeTexels, lookTexel(l, LOOK_COLOR1_TEXEL)).w; }
vec3 lookColor1(uint l) { return uintBitsToFloat(texelFetch(nodeTexels, lookTexel(l, LOOK_COLOR1_TEXEL)).xyz); }
vec3 lookColor2(uint l) { return uintBitsToFloat(texelFetch(nodeTexels, lookTexel(l, LOOK_COLOR2_TEXEL)).xyz); }
vec4r lookChecker(uint l) { return realVec4At(nodeTexels, lookTexel(l, int(LOOK_CHECKER_TEXEL))); }
vec4r lightPosition(uint i) { return realVec4At(lightTexels, LIGHT_TEXELS * int(i)); }
vec4r lightPower(uint i) { return realVec4At(lightTexels, LIGHT_TEXELS * int(i) + REAL_VEC4_TEXELS); }
#endif

#endif  // HEXRAY_SCENE_DATA_GLSL
