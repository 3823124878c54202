#include "camera/camera.h"

#include <cmath>

#include <glm/trigonometric.hpp>

namespace hexray::inline camera {

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

}  // namespace hexray::camera
