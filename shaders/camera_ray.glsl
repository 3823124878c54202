// Primary rays through the course's pixel sheet (set up on the host, see host/camera/camera.h).
#ifndef HEXRAY_CAMERA_RAY_GLSL
#define HEXRAY_CAMERA_RAY_GLSL

#include "precision.glsl"
#include "ray.glsl"
#include "render_outputs.glsl"
#include "scene_data.glsl"

// Sample `index` of the pixel, as host/camera/camera.cpp's sampleOffset places it: a
// stratified Hammersley pattern over the pixel's footprint, one sample at samplingOffset.
vec2r sampleOffset(uint index) {
    real u = (real(index) + 0.5) / real(SAMPLES_PER_PIXEL);
    real radicalInverse = real(bitfieldReverse(index)) * 2.3283064365386963e-10;  // 2^-32
    real v = fract(radicalInverse + 0.5 / real(SAMPLES_PER_PIXEL));
    return vec2r(u, v) - (0.5 - real(frame.samplingOffset));
}

Ray primaryRay(uvec2 pixel, uint sampleIndex) {
    vec2r s = (vec2r(pixel) + sampleOffset(sampleIndex)) / vec2r(frame.imageSize);
    vec3r target = frame.sheetTopLeft.xyz + frame.sheetRight.xyz * s.x + frame.sheetDown.xyz * s.y;
    // Camera rays start at the eye exactly and accept any t > 0. A generated kernel for a
    // camera-relative scene knows the eye is at 0, and so does its compiler.
#ifdef HEXRAY_EYE_AT_ORIGIN
    return Ray(vec3r(0.0), normalize(target));
#else
    return Ray(frame.origin.xyz, normalize(target));
#endif
}

#endif  // HEXRAY_CAMERA_RAY_GLSL
