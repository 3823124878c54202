// The arithmetic of positions and distances: float, or double when compiled with HEXRAY_F64.
// Colours are always float.
#ifndef HEXRAY_PRECISION_GLSL
#define HEXRAY_PRECISION_GLSL

#include "unit_roundoff.h"

#ifdef HEXRAY_F64
#define real double
#define vec2r dvec2
#define vec3r dvec3
#define vec4r dvec4
const double REAL_MAX = 1.0e300lf;                      // farther than any hit
const double UNIT_ROUNDOFF = FLOAT64_UNIT_ROUNDOFF;
#else
#define real float
#define vec2r vec2
#define vec3r vec3
#define vec4r vec4
const float REAL_MAX = 3.4028235e38;       // farther than any hit (GLSL has no constant infinity)
const float UNIT_ROUNDOFF = FLOAT32_UNIT_ROUNDOFF;
#endif

const float FLOAT_MAX = 3.4028235e38;  // colours' largest finite value

// pbrt's gamma(n) in this kernel's precision (unit_roundoff.h): a macro, so that constants can use it.
#define gamma(n) HEXRAY_GAMMA(real(n), UNIT_ROUNDOFF)

#endif  // HEXRAY_PRECISION_GLSL
