#include "camera/camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace hexray {

glm::dmat3 cameraRotation(const CameraSettings& camera) {
    const glm::dmat4 identity(1.0);
    const glm::dmat4 yaw = glm::rotate(identity, glm::radians(-camera.yawDegrees), {0.0, 1.0, 0.0});
    const glm::dmat4 pitch = glm::rotate(identity, glm::radians(-camera.pitchDegrees), {1.0, 0.0, 0.0});
    const glm::dmat4 roll = glm::rotate(identity, glm::radians(-camera.rollDegrees), {0.0, 0.0, 1.0});
    return glm::dmat3(yaw * pitch * roll);
}

glm::dvec3 cameraForward(const CameraSettings& camera) {
    return cameraRotation(camera) * glm::dvec3(0.0, 0.0, 1.0);
}

PixelSheet makePixelSheet(const CameraSettings& camera, double aspect) {
    // Unscaled corners are (+-aspect, +-1, 1); scaling by m makes the half-diagonal tan(fov/2).
    const double m = std::tan(glm::radians(camera.fovDegrees) / 2.0) / std::sqrt(aspect * aspect + 1.0);
    const glm::dvec3 topLeft(-aspect * m, m, 1.0);
    const glm::dvec3 topRight(aspect * m, m, 1.0);
    const glm::dvec3 bottomLeft(-aspect * m, -m, 1.0);

    const glm::dmat3 rotation = cameraRotation(camera);
    PixelSheet sheet;
    sheet.origin = camera.position;
    sheet.topLeft = rotation * topLeft;
    sheet.right = rotation * (topRight - topLeft);
    sheet.down = rotation * (bottomLeft - topLeft);
    return sheet;
}

}  // namespace hexray
