#version 450
// lavapipe's ceiling for the lecture demo scene (scenes/lecture-demo.json): a hand-written,
// straight-line kernel with the scene's values as literals, in float, with the textbook
// arithmetic (b^2 - c discriminant, shadow rays nudged off by 1e-3 t). It is not a renderer:
// `hexray bench` times it beside the renderer, as the yardstick for the kernel hexray generates
// for the scene. Only the eye is hard-wired with the scene; the camera's sheet,
// image size, sampling offset and output encoding come from the host as for render.comp.
#extension GL_GOOGLE_include_directive : require
#define HEXRAY_UNIFORM_SCENE

#include "encode.glsl"
#include "render_outputs.glsl"
#include "scene_data.glsl"

const vec3 EYE = vec3(0.0, 60.0, -120.0);
const vec3 BALL_CENTRE = vec3(-10.0, 60.0, 0.0);
const float BALL_RADIUS = 10.0;
const vec3 LIGHT = vec3(30.0, 100.0, -70.0);
const float LIGHT_INTENSITY = 10000.0;
const float AMBIENT = 0.15;
const float CHECKER_SIZE = 20.0;
const float FAR = 3.0e38;

// Nearest t > 0 of a ray from `origin` on the ball, or FAR.
float ballDistance(vec3 origin, vec3 direction) {
    vec3 f = origin - BALL_CENTRE;
    float b = dot(f, direction);
    float discriminant = b * b - (dot(f, f) - BALL_RADIUS * BALL_RADIUS);
    float root = sqrt(max(discriminant, 0.0));
    float near = -b - root;
    float t = near > 0.0 ? near : -b + root;
    return discriminant >= 0.0 && t > 0.0 ? t : FAR;
}

void main() {
    uvec2 pixel = bandPixel();
    if (pixel.x >= frame.imageSize.x || pixel.y >= band.rowCount) {
        return;
    }
    vec2 s = (vec2(pixel.x, band.firstRow + pixel.y) + frame.samplingOffset) / vec2(frame.imageSize);
    vec3 d = normalize(frame.sheetTopLeft.xyz + frame.sheetRight.xyz * s.x + frame.sheetDown.xyz * s.y);

    float floorT = -EYE.y / d.y;
    floorT = floorT > 0.0 ? floorT : FAR;
    float ballT = ballDistance(EYE, d);
    bool ball = ballT < floorT;
    float t = min(ballT, floorT);
    vec3 p = EYE + t * d;
    vec3 n = ball ? (p - BALL_CENTRE) / BALL_RADIUS : vec3(0.0, 1.0, 0.0);
    bool odd = ((int(floor(p.x / CHECKER_SIZE)) + int(floor(p.z / CHECKER_SIZE))) & 1) != 0;
    vec3 albedo = ball ? vec3(0.8, 0.0, 0.0) : odd ? vec3(0.2, 0.3, 0.6) : vec3(0.0, 0.0, 0.8);

    vec3 toLight = LIGHT - p;
    float r2 = dot(toLight, toLight);
    float cosTheta = dot(n, toLight) * inversesqrt(r2);
    vec3 shadowOrigin = p + 1e-3 * t * n;
    vec3 shadowPath = LIGHT - shadowOrigin;
    float shadowLength = length(shadowPath);
    // Only the ball can come between: the floor cannot separate a point on or above it from a
    // light above it.
    bool blocked = ballDistance(shadowOrigin, shadowPath / shadowLength) < shadowLength;
    float irradiance = AMBIENT + (cosTheta > 0.0 && !blocked ? LIGHT_INTENSITY * cosTheta / r2 : 0.0);
    vec3 color = t < FAR ? albedo * irradiance : vec3(0.0);
    encodedPixels[pixel.y * frame.imageSize.x + pixel.x] = encode8(color);
}
