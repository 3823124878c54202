#pragma once
// `hexray pixel`'s trace: one pixel explained by the shader itself (OUTPUT_TRACE). The request
// the host writes into the trace buffer, and the shader's answer read back from it, in world units.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "image/pixel_class.h"
#include "precision/arithmetic.h"
#include "precision/precision.h"
#include "scene/scene.h"
#include "shader_interface.h"

namespace hexray::inline gpu {

// One light at a traced sample, as the shader saw it.
struct GpuTraceLight {
    std::uint32_t status = gpu::TRACE_LIGHT_NOT_EVALUATED;  // gpu::TRACE_LIGHT_*
    double cosTheta = 0;
    double distanceSquared = 0;  // world units²
    double shadowLength = 0;     // world units
    glm::vec3 contribution{0};   // colour × intensity × cos θ / r²
};

// One pixel explained by the shader itself (OUTPUT_TRACE). Everything is converted back to
// world units: the placement's eye is added back and lengths multiplied by its scale, in
// double, from the shader's f32 or f64 values.
struct GpuPixelTrace {
    Precision precision = Precision::F32;
    bool cameraRelative = true;
    double scale = 1.0;  // the placement's power of two (1 for world placement)
    glm::dvec3 rayOrigin{0};
    glm::dvec3 rayDirection{0};
    std::vector<double> candidates;  // per node: t in world units, +inf for a miss
    std::uint32_t node = PixelClass::kBackground;
    std::uint32_t flags = 0;  // as PixelClass::flags
    double t = 0;
    glm::dvec3 position{0};
    glm::dvec3 normal{0};  // shading normal
    glm::dvec3 shadowOrigin{0};
    glm::vec3 albedo{0};
    glm::vec3 sampleColor{0};  // the traced sample's linear colour
    glm::vec3 pixelColor{0};   // the pixel's (average of its samples)
    std::vector<GpuTraceLight> lights;
    bool usedCandidateLists = false;  // the trace followed the candidate lists, as the scene's render does
    // f32-certified: a decision of the pixel was in doubt, and this is the f64 pass's trace of it.
    bool tracedAgainInF64 = false;
    bool inDoubt = false;  // the certified kernel's flag (false for every other kernel)
};

// The trace buffer's contents before the dispatch: which pixel and sample to trace, with room
// for the shader's answer (a header and an entry per node and per light) in `width`'s layout.
std::vector<std::byte> traceRequest(const Scene& scene, FloatWidth width, std::uint32_t x, std::uint32_t y,
                                    std::uint32_t sample);

// The shader's answer in the trace buffer, converted back to world units: the placement's eye
// added back and lengths multiplied by its scale, in double. Throws if the dispatch wrote nothing.
GpuPixelTrace unpackTrace(const Scene& scene, FloatWidth width, const std::byte* bytes, const Placement& placement);

}  // namespace hexray::gpu
