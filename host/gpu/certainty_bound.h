#pragma once
// f32-certified's bound on float32's error, and the scenes it certifies.

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace hexray::inline gpu {

// Float32's error in a decision, per unit of the decision's scale (shaders/certified.glsl), for
// camera rays through the sheet (topLeft + right s.x + down s.y, s in [0, 1]^2, from the eye):
// CERTAINTY_MARGIN times the near-tie bound (decision_roundoff.h nearTieUnits) of the sheet's worst
// ray, so that the kernel's own rounding of a margin cannot pass a decision the reference calls
// near-tied. Over the sheet the terms are at most |topLeft| + |right| + |down| and the target no
// nearer than the sheet's plane.
double certaintyBound(const glm::dvec3& topLeft, const glm::dvec3& right, const glm::dvec3& down);

// Why f32-certified cannot render `scene` (which then renders in f64), or nothing. It certifies
// the decisions of a generated kernel for an eye outside every sphere, clear of its surface by more
// than the bound: the eye's side of a sphere decides every ray, and the host decides it in double.
std::optional<std::string> certificationProblem(const Scene& scene, bool generatedKernel);

}  // namespace hexray::gpu
