// Rays and the hits along them.
#ifndef HEXRAY_RAY_GLSL
#define HEXRAY_RAY_GLSL

#include "shader_interface.h"
#include "precision.glsl"

struct Ray {
    vec3r origin;
    vec3r direction;  // unit length
};

const real NO_HIT = REAL_MAX;
const uint NO_NODE = BACKGROUND;

struct Hit {
    real t;
    uint node;
};

#endif  // HEXRAY_RAY_GLSL
