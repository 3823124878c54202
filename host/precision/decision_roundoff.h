#pragma once
// What the CPU reference's margins are read against when it is compared with a GPU render.

#include "precision/arithmetic.h"
#include "precision/precision.h"

namespace hexray::inline precision {

// The unit roundoff of the arithmetic a comparison tests, per kind of decision: float32's 2^-24
// by default; double's 2^-53 for what a float64 shader computes in double.
struct DecisionRoundoff {
    double general = unitRoundoff(FloatWidth::F32);
    double sphereChecker =
        unitRoundoff(FloatWidth::F32);  // a sphere's checker cell, from its angular texture coordinates
};

// The unit roundoff the shader makes each kind of decision with in `precision` (never Auto):
// f64 computes in double, except a sphere's angular texture coordinates
// (GLSL has no double atan, so they stay float); f32 and f32-naive compute in float.
// f32-certified decides as f64 does: where float's decision is within its error bound, f64 decides.
DecisionRoundoff decisionRoundoff(Precision precision);

}  // namespace hexray::precision
