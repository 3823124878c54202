// The unit roundoff of float32 and float64, half a unit in the last place of 1 (2^-24, 2^-53): the
// unit every error bound in hexray is counted in. Read by C++ (the CPU reference's margins, the
// candidate lists' padding, a comparison's roundoff) and by GLSL (precision.glsl), so that both
// sides hold one definition. The decimals are the powers of two exactly.
#ifndef HEXRAY_UNIT_ROUNDOFF_H
#define HEXRAY_UNIT_ROUNDOFF_H

// pbrt's gamma(n): n u / (1 - n u) bounds the relative error that n successive roundings in unit
// roundoff u can leave (Higham, Accuracy and Stability of Numerical Algorithms, 3.1), while n u < 1.
// A macro so that GLSL constants can use it (precision.glsl's gamma(n)).
#define HEXRAY_GAMMA(n, unitRoundoff) ((n) * (unitRoundoff) / (1.0 - (n) * (unitRoundoff)))

// A lit light's term carries roundoff of r^2, of the direction and of the normal, LIGHT_TERM_UNITS
// units each; past LIGHT_TERM_TOLERANCE (an 8-bit level of a full-bright linear channel) two correct
// renderers may differ by a level (cpu_margins.h lightTermMargin; certified.glsl certifyLightTerm).
// f32-certified checks every decision against CERTAINTY_MARGIN times the reference's near-tie bound,
// so that its own rounding of a margin cannot pass a near-tied decision (gpu/certainty_bound.h).
#ifdef __cplusplus
namespace hexray {
inline constexpr double FLOAT32_UNIT_ROUNDOFF = 5.9604644775390625e-8;
inline constexpr double FLOAT64_UNIT_ROUNDOFF = 1.1102230246251565404236316680908203125e-16;
static_assert(FLOAT32_UNIT_ROUNDOFF == 0x1p-24 && FLOAT64_UNIT_ROUNDOFF == 0x1p-53);
inline constexpr double LIGHT_TERM_TOLERANCE = 0.00390625;
inline constexpr double LIGHT_TERM_UNITS = 4.0;
inline constexpr double CERTAINTY_MARGIN = 2.0;
static_assert(LIGHT_TERM_TOLERANCE == 0x1p-8);
}  // namespace hexray
#else
const float LIGHT_TERM_TOLERANCE = 0.00390625;
const float LIGHT_TERM_UNITS = 4.0;
const float CERTAINTY_MARGIN = 2.0;
const float FLOAT32_UNIT_ROUNDOFF = 5.9604644775390625e-8;
#ifdef HEXRAY_F64  // a double constant would make every kernel need float64
const double FLOAT64_UNIT_ROUNDOFF = 1.1102230246251565404236316680908203125e-16lf;
#endif
#endif

#endif  // HEXRAY_UNIT_ROUNDOFF_H
