#pragma once
// The course's rectilinear pinhole camera, set up on the host in double precision.
// Both renderers start from the same PixelSheet; each interpolates its own rays from it.

#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/camera_angles.h"  // the angles' meaning: the camera's rotation
#include "scene/scene.h"

namespace hexray::inline camera {

// The "sheet" at distance 1 in front of the camera, already rotated into world space.
// The ray through image point (sx, sy) of a W x H image aims at
//   topLeft + right * (sx / W) + down * (sy / H),
// where right = TR - TL and down = BL - TL.
struct PixelSheet {
    glm::dvec3 origin{0.0};
    glm::dvec3 topLeft{0.0};
    glm::dvec3 right{0.0};
    glm::dvec3 down{0.0};
};

// The sheet for a FOV measured across the diagonal of a sheet of the given aspect.
PixelSheet makePixelSheet(const CameraSettings& camera, double aspect);

// Where inside pixel (x, y) its ray aims: 0.5 for centres, 0 for the course's corners.
inline double samplingOffset(Sampling sampling) {
    return sampling == Sampling::Center ? 0.5 : 0.0;
}

// Where sample `index` of `count` aims, as an offset from pixel (x, y): a stratified
// Hammersley pattern, u = (i + 0.5) / n, v = radical inverse of i in base 2 + 0.5 / n (mod 1),
// over the pixel's footprint: the unit square with samplingOffset at its centre. One sample is
// exactly samplingOffset. The shader computes the same pattern (shaders/camera_ray.glsl).
glm::dvec2 sampleOffset(std::uint32_t index, std::uint32_t count, Sampling sampling);

// Where sample `sample` of pixel (x, y) lies on the sheet, as fractions (s.x, s.y) of its width
// and height: the ray aims at topLeft + right * s.x + down * s.y.
glm::dvec2 sheetPosition(const ImageSettings& image, std::uint32_t x, std::uint32_t y, std::uint32_t sample);

// The unit direction from the eye through sample `sample` of pixel (x, y), in double: what the
// CPU reference's (and the bench's Embree renderer's) camera rays follow.
glm::dvec3 sampleDirection(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t x, std::uint32_t y,
                           std::uint32_t sample);

}  // namespace hexray::camera
