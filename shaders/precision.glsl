// The arithmetic of positions and distances: float, or double when compiled with HEXRAY_F64.
// Colours are always float.
#ifndef HEXRAY_PRECISION_GLSL
#define HEXRAY_PRECISION_GLSL

#ifdef HEXRAY_F64
#define real double
#define vec2r dvec2
#define vec3r dvec3
#define vec4r dvec4
const double REAL_MAX = 1.0e300lf;                      // farther than any hit
const double UNIT_ROUNDOFF = 1.1102230246251565e-16lf;  // 2^-53
#else
#define real float
#define vec2r vec2
#define vec3r vec3
#define vec4r vec4
const float REAL_MAX = 3.4028235e38;       // farther than any hit (GLSL has no constant infinity)
const float UNIT_ROUNDOFF = 5.9604645e-8;  // 2^-24
#endif

const float FLOAT_MAX = 3.4028235e38;  // colours' largest finite value

#endif  // HEXRAY_PRECISION_GLSL
