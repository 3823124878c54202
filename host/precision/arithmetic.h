#pragma once
// The shader's arithmetic as the plan decides it: the float width, the formulation, and where
// world coordinates go before they are rounded to the shader's floats.

#include <glm/vec3.hpp>

#include "unit_roundoff.h"

namespace hexray::inline precision {

// The shader's arithmetic for positions and distances (colours are always float).
enum class FloatWidth { F32, F64 };

// The unit roundoff of a float width (shaders/unit_roundoff.h: the figures C++ and GLSL share).
constexpr double unitRoundoff(FloatWidth width) {
    return width == FloatWidth::F64 ? FLOAT64_UNIT_ROUNDOFF : FLOAT32_UNIT_ROUNDOFF;
}

// Textbook: the formulas as a course writes them (f32-naive). Robust: cancellation-free
// intersections, hit points on the surface, error-bound shadow offsets; a generated kernel
// still uses the cheaper fast form for the nodes whose conditioning allows it (NodeCode).
enum class Formulation { Textbook, Robust };

// Where world coordinates go before they are rounded to the shader's floats.
struct Placement {
    // Camera-relative: subtract the eye in double and divide every length by `scale`, a power of
    // two near the geometric middle of the scene's lengths (placementScale), so both steps are
    // exact: far-off scenes lose no precision, and very large or very small ones neither overflow
    // nor underflow. Otherwise world coordinates as given.
    bool cameraRelative = true;
    glm::dvec3 origin{0.0};  // the world point placed at 0: the eye, or 0
    double scale = 1.0;
    glm::dvec3 position(const glm::dvec3& world) const { return (world - origin) / scale; }
    double length(double world) const { return world / scale; }
};

}  // namespace hexray::precision
