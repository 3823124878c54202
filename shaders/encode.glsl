// The 8-bit output, as host/image/image_io.cpp's encodeChannel computes it: clamp to [0, 1],
// the sRGB transfer function unless the scene asks for linear output, round to nearest.
#ifndef HEXRAY_ENCODE_GLSL
#define HEXRAY_ENCODE_GLSL

#include "render_outputs.glsl"

uint encode8(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    if (OUTPUT_MODE == OUTPUT_8BIT_SRGB) {
        c = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
    }
    uvec3 level = uvec3(floor(c * 255.0 + 0.5));
    return level.r | (level.g << 8) | (level.b << 16) | ENCODED_ALPHA_BITS;
}

#endif  // HEXRAY_ENCODE_GLSL
