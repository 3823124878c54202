#pragma once
// Embree 3 as a yardstick for `hexray bench`: the same scenes, camera rays and shading model,
// traced by Intel's CPU ray-tracing kernels, so the bench can say how far hexray's backends
// are from a well-tuned CPU tracer. Built only when CMake finds Embree 3; nothing else in
// hexray depends on it.
//
// Embree traverses and intersects in float. The spheres are RTC_GEOMETRY_TYPE_SPHERE_POINT,
// uploaded camera-relative (as the f32 shader does) so that float loses nothing to the scene's
// position; planes are unbounded and tested analytically. The hit point is rebuilt from
// Embree's t and shaded in double with the CPU reference's texture helpers. How the rays go
// to Embree is the caller's choice (EmbreeTracing); the image is the same either way.

#include <cstdint>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include "image/image.h"
#include "image/pixel_class.h"
#include "scene/scene.h"

namespace hexray::inline embree {

struct EmbreeRender {
    Image image;                      // linear, like the CPU reference's
    std::vector<PixelClass> classes;  // of each pixel's first sample, like the other renderers
    double renderMilliseconds = 0;    // tracing and shading every sample, all threads
};

// Rays per packet in EmbreeTracing::Packets: Embree's 8-wide kernels (AVX2 and AVX-512).
inline constexpr std::uint32_t kEmbreePacketSize = 8;

enum class EmbreeTracing {
    // One ray at a time: rtcIntersect1 (camera rays, flagged coherent) and rtcOccluded1.
    SingleRays,
    // Coherent packets: the camera rays of a tile of 4 x 2 pixels (one sample each) in one
    // rtcIntersect8, then for each light the shadow rays those pixels need in one rtcOccluded8.
    Packets,
};

// "single rays" or "8-ray packets", for tables.
std::string tracingName(EmbreeTracing tracing);

class EmbreeRenderer {
public:
    // `threadCount` threads trace rows; Embree's own builder is told to use as many.
    explicit EmbreeRenderer(unsigned threadCount);
    ~EmbreeRenderer();
    EmbreeRenderer(const EmbreeRenderer&) = delete;
    EmbreeRenderer& operator=(const EmbreeRenderer&) = delete;

    EmbreeRender render(const Scene& scene, EmbreeTracing tracing = EmbreeTracing::SingleRays) const;
    unsigned threadCount() const { return threadCount_; }
    std::string version() const;  // "Embree 3.13.5", from the library actually loaded

private:
    RTCDevice device_ = nullptr;
    unsigned threadCount_;
};

}  // namespace hexray::embree
