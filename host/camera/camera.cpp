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

glm::dvec2 sampleOffset(std::uint32_t index, std::uint32_t count, Sampling sampling) {
    std::uint32_t reversed = index;  // bit reversal of a 32-bit index
    reversed = (reversed << 16) | (reversed >> 16);
    reversed = ((reversed & 0x00ff00ffu) << 8) | ((reversed & 0xff00ff00u) >> 8);
    reversed = ((reversed & 0x0f0f0f0fu) << 4) | ((reversed & 0xf0f0f0f0u) >> 4);
    reversed = ((reversed & 0x33333333u) << 2) | ((reversed & 0xccccccccu) >> 2);
    reversed = ((reversed & 0x55555555u) << 1) | ((reversed & 0xaaaaaaaau) >> 1);
    const double u = (double(index) + 0.5) / double(count);
    const double radicalInverse = double(reversed) * 0x1p-32;
    const double v = std::fmod(radicalInverse + 0.5 / double(count), 1.0);
    return glm::dvec2(u, v) - (0.5 - samplingOffset(sampling));
}

glm::dvec2 sheetPosition(const ImageSettings& image, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    const glm::dvec2 offset = sampleOffset(sample, image.samplesPerPixel, image.sampling);
    return {(double(x) + offset.x) / double(image.width), (double(y) + offset.y) / double(image.height)};
}

glm::dvec3 sampleDirection(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t x, std::uint32_t y,
                           std::uint32_t sample) {
    const glm::dvec2 s = sheetPosition(image, x, y, sample);
    return glm::normalize(sheet.topLeft + sheet.right * s.x + sheet.down * s.y);
}

}  // namespace hexray
