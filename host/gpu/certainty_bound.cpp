#include "gpu/certainty_bound.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "gpu/render_plan.h"
#include "precision/decision_roundoff.h"
#include "unit_roundoff.h"

namespace hexray::inline gpu {

double certaintyBound(const glm::dvec3& topLeft, const glm::dvec3& right, const glm::dvec3& down) {
    const glm::dvec3 terms = glm::abs(topLeft) + glm::abs(right) + glm::abs(down);
    const double nearest = std::abs(glm::dot(topLeft, glm::normalize(glm::cross(right, down))));
    const double directionUnits = cameraDirectionUnits(std::max({terms.x, terms.y, terms.z}), nearest);
    return CERTAINTY_MARGIN * nearTieUnits(directionUnits) * FLOAT32_UNIT_ROUNDOFF;
}

std::optional<std::string> certificationProblem(const Scene& scene, bool generatedKernel) {
    if (!isSmallScene(scene) || !generatedKernel) {
        return "it certifies generated kernels only, for scenes of up to 32 nodes and 32 lights";
    }
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const double bound = certaintyBound(sheet.topLeft, sheet.right, sheet.down);
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            const double distance = glm::length(sphere->center - scene.camera.position);
            if (!(distance - sphere->radius > bound * (distance + sphere->radius))) {
                return "the eye is inside a sphere or within float32's error of its surface";
            }
        }
    }
    return std::nullopt;
}

}  // namespace hexray::gpu
