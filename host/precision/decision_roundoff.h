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

// How far roundoff can move the unit direction of a camera ray as the shader forms it, in units of
// roundoff: topLeft + right * s.x + down * s.y from float copies of the sheet, each component off by
// up to 8 units of its terms' largest magnitude `largestTerm` (the copies, s itself, the product,
// two sums), over the target's length `targetLength`; normalizing adds 5 (the dot product, a 2-ulp
// inverse square root, the product).
constexpr double cameraDirectionUnits(double largestTerm, double targetLength) {
    return 8.0 * largestTerm / targetLength + 5.0;
}

// The relative margin below which a decision of one camera ray is near-tied, in units of roundoff:
// twice a bound on how far roundoff moves it, the direction's units and 16 for the float copies of
// the scene and the decision's own chain of operations. The CPU reference's comparisons and
// f32-certified's bound (host/gpu/certainty_bound.h) both count in it.
constexpr double nearTieUnits(double directionUnits) {
    return 2.0 * (directionUnits + 16.0);
}

// The unit roundoff the shader makes each kind of decision with in `precision` (never Auto):
// f64 computes in double, except a sphere's angular texture coordinates
// (GLSL has no double atan, so they stay float); f32 and f32-naive compute in float.
// f32-certified decides as f64 does: where float's decision is within its error bound, f64 decides.
DecisionRoundoff decisionRoundoff(Precision precision);

}  // namespace hexray::precision
