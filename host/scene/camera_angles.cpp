#include "scene/camera_angles.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace hexray::inline scene {

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

CameraAngles lookAtAngles(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    const glm::dvec3 view = target - position;
    // forward = (-sin yaw cos pitch, sin pitch, cos yaw cos pitch); no normalising needed.
    CameraAngles angles;
    angles.yawDegrees = glm::degrees(std::atan2(-view.x, view.z));
    angles.pitchDegrees = glm::degrees(std::atan2(view.y, std::hypot(view.x, view.z)));
    // Roll turns the unrolled camera's up toward its right: measure `up` in that frame.
    CameraSettings unrolledCamera;
    unrolledCamera.yawDegrees = angles.yawDegrees;
    unrolledCamera.pitchDegrees = angles.pitchDegrees;
    const glm::dmat3 unrolled = cameraRotation(unrolledCamera);
    const glm::dvec3 right = unrolled * glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 unrolledUp = unrolled * glm::dvec3(0.0, 1.0, 0.0);
    angles.rollDegrees = glm::degrees(std::atan2(glm::dot(up, right), glm::dot(up, unrolledUp)));
    return angles;
}

}  // namespace hexray::scene
