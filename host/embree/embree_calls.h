#pragma once
// What every Embree renderer here needs around Embree's calls: errors as exceptions, and the
// intersection context for a kind of ray.

#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace hexray::inline embree {

// Throws when the last call on `device` failed.
inline void checkEmbree(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree: ") + what + " failed (RTCError " + std::to_string(error) + ")");
    }
}

// A context for rays that are coherent (a tile's camera rays) or not (shadow rays).
inline RTCIntersectContext intersectContext(RTCIntersectContextFlags flags) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = flags;
    return context;
}

}  // namespace hexray::embree
