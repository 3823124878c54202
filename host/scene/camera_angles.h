#pragma once
// What a scene's camera angles mean (the course's yaw, pitch and roll): the rotation they make,
// and the angles of a look-at camera, which the loader converts once so that nothing downstream
// knows the difference.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace hexray::inline scene {

// Roll first, then pitch, then yaw: rotate(-yaw, Y) * rotate(-pitch, X) * rotate(-roll, Z).
glm::dmat3 cameraRotation(const CameraSettings& camera);

// The direction the camera looks along (the rotated +Z axis).
glm::dvec3 cameraForward(const CameraSettings& camera);

struct CameraAngles {
    double yawDegrees = 0.0;
    double pitchDegrees = 0.0;
    double rollDegrees = 0.0;
};

// The angles of a camera at `position` looking at `target`, with the unit vector `up` pointing up in
// the image as nearly as it can (its part across the view): the scene file's look-at camera, as
// the course's angles. The caller rejects a target at the position and an `up` along the view.
CameraAngles lookAtAngles(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up);

}  // namespace hexray::scene
