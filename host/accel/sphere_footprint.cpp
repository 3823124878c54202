#include "accel/sphere_footprint.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "accel/candidate_tunables.h"

namespace hexray::inline accel {
namespace {

using namespace candidates;  // the tunables

// The range of t = x / z over the tangent planes through the origin that touch a ball centred at
// (x, ., z), z > radius: the roots of (x - t z)^2 = radius^2 (1 + t^2).
void tangentRange(double x, double z, double radius, double& low, double& high) {
    const double denominator = (z - radius) * (z + radius);
    const double inverse = 1.0 / denominator;
    const double half = radius * std::sqrt(x * x + denominator);
    const double slack = kFootprintSlack * (1.0 + (x * x + z * z) * inverse);
    low = (x * z - half) * inverse - slack;
    high = (x * z + half) * inverse + slack;
}

// The range of a unit direction's component along an axis at angle `angle` from the ball's
// centre, over the cone of half-angle `halfAngle` around it.
void componentRange(double angle, double halfAngle, double& low, double& high) {
    low = std::cos(std::min(std::numbers::pi, angle + halfAngle));
    high = std::cos(std::max(0.0, angle - halfAngle));
}

}  // namespace

double TangentView::minForward() const {
    const double u = std::max(std::abs(window.u0), std::abs(window.u1));
    const double v = std::max(std::abs(window.v0), std::abs(window.v1));
    return (1.0 - kFootprintSlack) / std::sqrt(1.0 + u * u + v * v);
}

std::optional<TangentBox> ballFootprint(const TangentView& view, const glm::dvec3& center, double radius) {
    if (glm::dot(center, center) <= radius * radius) {
        return view.window;
    }
    const double x = glm::dot(center, view.right);
    const double y = glm::dot(center, view.down);
    const double z = glm::dot(center, view.forward);
    TangentBox box;
    if (z > radius) {
        // Wholly in front: the exact bounds of the projected ellipse.
        tangentRange(x, z, radius, box.u0, box.u1);
        tangentRange(y, z, radius, box.v0, box.v1);
    } else {
        // Across the plane of the origin: bound the cone of directions component by component,
        // and divide by the least forward component the window allows.
        const double distance = glm::length(center);
        const double halfAngle = std::asin(std::min(radius / distance, 1.0));
        const auto angle = [&](double component) { return std::acos(std::clamp(component / distance, -1.0, 1.0)); };
        double lowX, highX, lowY, highY, lowZ, highZ;
        componentRange(angle(x), halfAngle, lowX, highX);
        componentRange(angle(y), halfAngle, lowY, highY);
        componentRange(angle(z), halfAngle, lowZ, highZ);
        const double nearest = view.minForward();
        if (highZ < nearest) {
            return std::nullopt;
        }
        lowZ = std::max(lowZ, nearest);
        // acos near 0 and pi is ill-conditioned: a generous slack for the cosines.
        const double slack = 1e-7 / nearest;
        box.u0 = std::min(lowX / lowZ, lowX / highZ) - slack;
        box.u1 = std::max(highX / lowZ, highX / highZ) + slack;
        box.v0 = std::min(lowY / lowZ, lowY / highZ) - slack;
        box.v1 = std::max(highY / lowZ, highY / highZ) + slack;
    }
    box.u0 = std::max(box.u0, view.window.u0);
    box.v0 = std::max(box.v0, view.window.v0);
    box.u1 = std::min(box.u1, view.window.u1);
    box.v1 = std::min(box.v1, view.window.v1);
    if (!(box.u0 <= box.u1 && box.v0 <= box.v1)) {
        return std::nullopt;
    }
    return box;
}

}  // namespace hexray::accel
