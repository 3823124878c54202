#include "gpu/pixel_trace.h"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "layout/gpu_layout.h"

namespace hexray::inline gpu {
namespace {

template <typename Real>
GpuPixelTrace unpackTraceAs(const Scene& scene, const std::byte* bytes, const Placement& placement) {
    gpu::GpuTraceHeader<Real> header;
    std::memcpy(&header, bytes, sizeof header);
    if (header.result.x != 1) {
        throw std::runtime_error("internal error: the trace dispatch wrote nothing");
    }
    const double scale = placement.scale;
    const auto world = [&](const gpu::RealVec4<Real>& p) { return placement.origin + scale * glm::dvec3(p); };
    // The shader's NO_HIT is REAL_MAX: 1e300 in f64, FLT_MAX in f32.
    const double miss = std::is_same_v<Real, double> ? 1e299 : 1e38;
    const auto distance = [&](Real t) {
        return double(t) >= miss ? std::numeric_limits<double>::infinity() : double(t) * scale;
    };
    GpuPixelTrace trace;
    trace.cameraRelative = placement.cameraRelative;
    trace.scale = scale;
    trace.rayOrigin = world(header.rayOrigin);
    trace.rayDirection = glm::dvec3(header.rayDirection);
    trace.node = header.result.y;
    trace.flags = header.result.z;
    trace.inDoubt = header.result.w != 0;
    trace.t = distance(header.hitPosition.w);
    trace.position = world(header.hitPosition);
    trace.normal = glm::dvec3(header.hitNormal);
    trace.shadowOrigin = world(header.shadowOrigin);
    trace.albedo = glm::vec3(header.albedo);
    trace.sampleColor = glm::vec3(header.sampleColor);
    trace.pixelColor = glm::vec3(header.pixelColor);
    const std::byte* entries = bytes + sizeof header;
    const auto entry = [&](std::size_t i) {
        gpu::GpuTraceEntry<Real> e;
        std::memcpy(&e, entries + i * sizeof e, sizeof e);
        return e;
    };
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        trace.candidates.push_back(distance(entry(i).values.x));
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const gpu::GpuTraceEntry<Real> e = entry(scene.nodes.size() + i);
        trace.lights.push_back(GpuTraceLight{e.status.x, double(e.values.x), double(e.values.y) * scale * scale,
                                             double(e.values.z) * scale, glm::vec3(e.color)});
    }
    return trace;
}

template <typename Real>
std::vector<std::byte> traceRequestAs(const Scene& scene, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    std::vector<std::byte> bytes(sizeof(gpu::GpuTraceHeader<Real>) +
                                 (scene.nodes.size() + scene.lights.size()) * sizeof(gpu::GpuTraceEntry<Real>));
    const glm::uvec4 request(x, y, sample, 0);
    std::memcpy(bytes.data(), &request, sizeof request);
    return bytes;
}

}  // namespace

std::vector<std::byte> traceRequest(const Scene& scene, FloatWidth width, std::uint32_t x, std::uint32_t y,
                                    std::uint32_t sample) {
    return width == FloatWidth::F64 ? traceRequestAs<double>(scene, x, y, sample)
                                    : traceRequestAs<float>(scene, x, y, sample);
}

GpuPixelTrace unpackTrace(const Scene& scene, FloatWidth width, const std::byte* bytes, const Placement& placement) {
    return width == FloatWidth::F64 ? unpackTraceAs<double>(scene, bytes, placement)
                                    : unpackTraceAs<float>(scene, bytes, placement);
}

}  // namespace hexray::gpu
