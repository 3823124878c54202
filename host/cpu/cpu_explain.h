#pragma once
// The CPU reference's decisions for one pixel, from the reference's own functions
// (cpu_intersect, cpu_shading): what `hexray pixel` prints.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cpu/cpu_intersect.h"
#include "cpu/cpu_shading.h"
#include "image/pixel_class.h"
#include "scene/scene.h"

namespace hexray::inline cpu {

struct CpuPixelExplanation {
    Ray ray;                                     // of the explained sample
    std::vector<std::optional<Hit>> candidates;  // per node
    std::optional<SceneHit> nearest;
    bool constantShaded = false;
    Color albedo{0.0};                      // the shader's colour at the hit
    glm::dvec2 uv{0.0};                     // texture coordinates (checker only)
    std::optional<glm::dvec2> checkerCell;  // floor(u/size), floor(v/size) (checker only)
    std::vector<LightTerm> lights;          // empty for constant shaders and the background
    Color sampleColor{0.0};
    Color pixelColor{0.0};  // average over the pixel's samples, as renderOnCpu
    PixelClass pixelClass;  // of the explained sample (renderOnCpu uses sample 0)
};

// Sample `sample` of pixel (x, y); the caller checks the ranges.
CpuPixelExplanation explainPixel(const Scene& scene, std::uint32_t x, std::uint32_t y, std::uint32_t sample);

}  // namespace hexray::cpu
