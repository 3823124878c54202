#pragma once
// Where a ball shows in a perspective view: the box, in tangent coordinates, of every direction
// from the view's origin that meets it. The candidate lists (candidate_lists.h) bin spheres with
// it, into the camera's view and the six faces of a cube around each light.

#include <optional>

#include <glm/vec3.hpp>

namespace hexray::inline accel {

// A direction d shows at tangent coordinates (u, v) = (d . right, d . down) / (d . forward).
struct TangentBox {
    double u0 = 0;
    double v0 = 0;
    double u1 = 0;
    double v1 = 0;

    double width() const { return u1 - u0; }
    double height() const { return v1 - v0; }
};

// A view from a point: an orthonormal frame and the part of the tangent plane its rays cover.
struct TangentView {
    glm::dvec3 right{1, 0, 0};
    glm::dvec3 down{0, 1, 0};
    glm::dvec3 forward{0, 0, 1};
    TangentBox window;
    // The least d . forward of a unit direction d inside the window (at its farthest corner).
    double minForward() const;
};

// The box, clipped to the view's window, around the tangent coordinates of every direction from
// the view's origin that meets the ball of radius `radius` around `center` (relative to the
// origin), rounded outward; nothing when no such direction lies in the window. An origin inside the
// ball sees it everywhere: the whole window.
std::optional<TangentBox> ballFootprint(const TangentView& view, const glm::dvec3& center, double radius);

}  // namespace hexray::accel
