// Reading reals from a uniform texel buffer of RGBA32UI texels: a float takes one word, a double
// two, so a vector of four reals takes one texel in f32 and two in f64. lavapipe reads a texel
// buffer at a different index in each lane with vector loads; a storage buffer it reads one lane
// and one word at a time, each through the stack (shader_interface.h).
#ifndef HEXRAY_TEXELS_GLSL
#define HEXRAY_TEXELS_GLSL

#include "precision.glsl"

#ifdef HEXRAY_F64
const int REAL_VEC4_TEXELS = 2;
#else
const int REAL_VEC4_TEXELS = 1;
#endif

vec4r realVec4At(usamplerBuffer texels, int at) {
#ifdef HEXRAY_F64
    uvec4 a = texelFetch(texels, at);
    uvec4 b = texelFetch(texels, at + 1);
    return dvec4(packDouble2x32(a.xy), packDouble2x32(a.zw), packDouble2x32(b.xy), packDouble2x32(b.zw));
#else
    return uintBitsToFloat(texelFetch(texels, at));
#endif
}

// The real in the first words of texel `at`, and the word after it.
real realAt(usamplerBuffer texels, int at, out uint next) {
    uvec4 texel = texelFetch(texels, at);
#ifdef HEXRAY_F64
    next = texel.z;
    return packDouble2x32(texel.xy);
#else
    next = texel.y;
    return uintBitsToFloat(texel.x);
#endif
}

#endif  // HEXRAY_TEXELS_GLSL
