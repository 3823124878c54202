#pragma once
// Embree 3 as its authors would use it, the bench's yardstick: the widest ray packet the CPU
// traces natively (16 rays on AVX-512, 8 on AVX2, else 4), each packet the camera rays of a square
// tile of pixels (4 x 4, 4 x 2, 2 x 2), shadow rays in packets too, and shading in float over
// the packet's lanes (structure-of-arrays loops the compiler can vectorise), with denormals
// flushed to zero while it traces. The same camera rays and shading model as the CPU reference,
// in float and camera-relative, as hexray's f32 shader computes them, so that its image agrees
// with the reference outside near-tied pixels.
//
// Spheres are Embree's RTC_GEOMETRY_TYPE_SPHERE_POINT; planes, unbounded, are tested over the
// lanes analytically. Benchmark-only code: nothing outside the bench depends on it.

#include <cstdint>
#include <string>

#include <embree3/rtcore.h>

#include "embree/embree_renderer.h"
#include "scene/scene.h"

namespace hexray::inline embree {

// The widest packet this CPU runs and `device`'s Embree traces natively: 16, 8 or 4.
std::uint32_t widestNativePacket(RTCDevice device);

class EmbreePacketRenderer {
public:
    // `threadCount` threads trace tiles; Embree's builder is told to use as many. `packetWidth`
    // 4, 8 or 16 (Embree emulates one wider than the CPU's); 0: widestNativePacket.
    explicit EmbreePacketRenderer(unsigned threadCount, std::uint32_t packetWidth = 0);
    ~EmbreePacketRenderer();
    EmbreePacketRenderer(const EmbreePacketRenderer&) = delete;
    EmbreePacketRenderer& operator=(const EmbreePacketRenderer&) = delete;

    EmbreeRender render(const Scene& scene) const;
    std::uint32_t packetWidth() const { return packetWidth_; }
    unsigned threadCount() const { return threadCount_; }

private:
    RTCDevice device_ = nullptr;
    unsigned threadCount_;
    std::uint32_t packetWidth_;
};

}  // namespace hexray::embree
