#pragma once
// What the CPU reference's margins are read against when it is compared with a GPU render.

#include "cpu/cpu_margins.h"
#include "gpu/precision.h"

namespace hexray {

// The unit roundoff the shader makes each kind of decision with in `precision` (never Auto):
// f64 computes in double, except a sphere's angular texture coordinates
// (GLSL has no double atan, so they stay float); f32 and f32-naive compute in float.
DecisionRoundoff decisionRoundoff(Precision precision);

}  // namespace hexray
