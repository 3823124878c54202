#include "embree/embree_packet_renderer.h"

#include <xmmintrin.h>  // _mm_getcsr, _MM_SET_FLUSH_ZERO_MODE
#include <pmmintrin.h>  // _MM_SET_DENORMALS_ZERO_MODE

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "embree/embree_calls.h"
#include "embree/embree_float_scene.h"
#include "embree/render_in_bands.h"
#include "util/milliseconds_since.h"

namespace hexray::inline embree {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr std::uint32_t kNoSphere = ~0u;

// Embree's packet types and calls for a width, and the tile of pixels a packet traces.
template <std::uint32_t W>
struct PacketApi;

template <>
struct PacketApi<4> {
    using RayHit = RTCRayHit4;
    using Ray = RTCRay4;
    static constexpr std::uint32_t kTileWidth = 2;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* rays) {
        rtcIntersect4(valid, scene, context, rays);
    }
    static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Ray* rays) {
        rtcOccluded4(valid, scene, context, rays);
    }
};

template <>
struct PacketApi<8> {
    using RayHit = RTCRayHit8;
    using Ray = RTCRay8;
    static constexpr std::uint32_t kTileWidth = 4;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* rays) {
        rtcIntersect8(valid, scene, context, rays);
    }
    static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Ray* rays) {
        rtcOccluded8(valid, scene, context, rays);
    }
};

template <>
struct PacketApi<16> {
    using RayHit = RTCRayHit16;
    using Ray = RTCRay16;
    static constexpr std::uint32_t kTileWidth = 4;
    static void intersect(const int* valid, RTCScene scene, RTCIntersectContext* context, RayHit* rays) {
        rtcIntersect16(valid, scene, context, rays);
    }
    static void occluded(const int* valid, RTCScene scene, RTCIntersectContext* context, Ray* rays) {
        rtcOccluded16(valid, scene, context, rays);
    }
};

// Denormals flushed to zero while a thread traces, as Embree's tutorials run; the thread's own
// mode comes back after (the CPU reference, in the same process, must keep IEEE arithmetic).
class FlushDenormals {
public:
    FlushDenormals() : saved_(_mm_getcsr()) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    }
    ~FlushDenormals() { _mm_setcsr(saved_); }
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    unsigned saved_;
};

// One sample of each pixel of a tile, lane by lane (structure of arrays): camera-relative.
template <std::uint32_t W>
struct Lanes {
    alignas(64) int valid[W];  // Embree's mask: -1 for a pixel inside the image
    alignas(64) float dx[W], dy[W], dz[W];
    alignas(64) float t[W];
    alignas(64) std::uint32_t node[W];
    alignas(64) std::uint32_t sphere[W];  // primID, or kNoSphere
    alignas(64) float planeHeight[W];
    alignas(64) float px[W], py[W], pz[W];  // the hit point
    alignas(64) float ux[W], uy[W], uz[W];  // the outward normal (a plane's: facing)
    alignas(64) float nx[W], ny[W], nz[W];  // the normal facing the ray
    alignas(64) float ox[W], oy[W], oz[W];  // where shadow rays start
    alignas(64) float shadowOffset[W];
    alignas(64) int usesLights[W];
    alignas(64) float albedoR[W], albedoG[W], albedoB[W];
    alignas(64) float lightR[W], lightG[W], lightB[W];  // incident light; 1 for unlit looks
    alignas(64) std::uint32_t flags[W];
};

// The camera rays of sample `sample` of the tile at (left, top), as the f32 shader forms them.
template <std::uint32_t W>
void cameraRays(const EmbreeFloatScene& scene, std::uint32_t left, std::uint32_t top, std::uint32_t sample,
                Lanes<W>& lanes, typename PacketApi<W>::RayHit& rays) {
    constexpr std::uint32_t kTileWidth = PacketApi<W>::kTileWidth;
    const glm::vec2 offset = scene.sampleOffsets[sample];
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const std::uint32_t column = left + lane % kTileWidth;
        const std::uint32_t row = top + lane / kTileWidth;
        const float x = float(column);
        const float y = float(row);
        lanes.valid[lane] = x < scene.width && y < scene.height ? -1 : 0;
        const float sx = (x + offset.x) / scene.width;
        const float sy = (y + offset.y) / scene.height;
        const float tx = scene.topLeft.x + scene.right.x * sx + scene.down.x * sy;
        const float ty = scene.topLeft.y + scene.right.y * sx + scene.down.y * sy;
        const float tz = scene.topLeft.z + scene.right.z * sx + scene.down.z * sy;
        const float inverseLength = 1.0f / std::sqrt(tx * tx + ty * ty + tz * tz);
        lanes.dx[lane] = rays.ray.dir_x[lane] = tx * inverseLength;
        lanes.dy[lane] = rays.ray.dir_y[lane] = ty * inverseLength;
        lanes.dz[lane] = rays.ray.dir_z[lane] = tz * inverseLength;
        rays.ray.org_x[lane] = rays.ray.org_y[lane] = rays.ray.org_z[lane] = 0.0f;
        rays.ray.tnear[lane] = 0.0f;
        rays.ray.tfar[lane] = kInfinity;
        rays.ray.time[lane] = 0.0f;
        rays.ray.mask[lane] = ~0u;
        rays.ray.flags[lane] = 0;
        rays.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        rays.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
}

// Each lane's nearest hit: Embree's sphere, or a plane nearer (on a tie the earlier node).
template <std::uint32_t W>
void nearestHits(const EmbreeFloatScene& scene, const typename PacketApi<W>::RayHit& rays, Lanes<W>& lanes) {
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const bool sphere = rays.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID;
        lanes.t[lane] = sphere ? rays.ray.tfar[lane] : kInfinity;
        lanes.sphere[lane] = sphere ? rays.hit.primID[lane] : kNoSphere;
        lanes.node[lane] = sphere ? scene.sphereNodes[rays.hit.primID[lane]] : PixelClass::kBackground;
        lanes.planeHeight[lane] = 0.0f;
    }
    for (std::size_t plane = 0; plane < scene.planeHeights.size(); ++plane) {
        const float height = scene.planeHeights[plane];
        const std::uint32_t node = scene.planeNodes[plane];
        for (std::uint32_t lane = 0; lane < W; ++lane) {
            const float t = height / lanes.dy[lane];
            const bool nearer =
                t > 0.0f && t < kInfinity && (t < lanes.t[lane] || (t == lanes.t[lane] && node < lanes.node[lane]));
            lanes.t[lane] = nearer ? t : lanes.t[lane];
            lanes.node[lane] = nearer ? node : lanes.node[lane];
            lanes.sphere[lane] = nearer ? kNoSphere : lanes.sphere[lane];
            lanes.planeHeight[lane] = nearer ? height : lanes.planeHeight[lane];
        }
    }
}

// The hit points, normals and shadow-ray origins. A sphere's normal comes from the
// intersection's small quantities (l, the centre's offset to the ray's closest point, and the
// half-chord), as the f32 shader's does: o + t d - c would subtract numbers as large as the
// distance. Its point is reprojected onto the sphere; a plane's is snapped onto the plane.
template <std::uint32_t W>
void surfaces(const EmbreeFloatScene& scene, Lanes<W>& lanes) {
    alignas(64) float cx[W], cy[W], cz[W], r[W];
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const bool sphere = lanes.sphere[lane] != kNoSphere;
        const glm::vec4 data = sphere ? scene.sphereData[lanes.sphere[lane]] : glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
        cx[lane] = data.x, cy[lane] = data.y, cz[lane] = data.z, r[lane] = data.w;
        lanes.shadowOffset[lane] = sphere ? scene.shadowOffsets[lanes.sphere[lane]] : 0.0f;
    }
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const float dx = lanes.dx[lane], dy = lanes.dy[lane], dz = lanes.dz[lane];
        const float b = -(cx[lane] * dx + cy[lane] * dy + cz[lane] * dz);  // f = o - c = -c; b = f.d
        const float lx = -cx[lane] - b * dx, ly = -cy[lane] - b * dy, lz = -cz[lane] - b * dz;
        const float lineDistance = std::sqrt(lx * lx + ly * ly + lz * lz);
        const float halfChord = std::sqrt(std::max((r[lane] - lineDistance) * (r[lane] + lineDistance), 0.0f));
        // From outside the near root, from inside the far one.
        const bool outside = cx[lane] * cx[lane] + cy[lane] * cy[lane] + cz[lane] * cz[lane] > r[lane] * r[lane];
        const float chord = outside ? -halfChord : halfChord;
        const float sx = lx + chord * dx, sy = ly + chord * dy, sz = lz + chord * dz;
        const float inverseLength = 1.0f / std::sqrt(sx * sx + sy * sy + sz * sz);
        const float ux = sx * inverseLength, uy = sy * inverseLength, uz = sz * inverseLength;
        const float turn = ux * dx + uy * dy + uz * dz > 0.0f ? -1.0f : 1.0f;
        const bool plane = lanes.sphere[lane] == kNoSphere;
        const float planeNormal = dy < 0.0f ? 1.0f : -1.0f;
        lanes.px[lane] = plane ? lanes.t[lane] * dx : cx[lane] + r[lane] * ux;
        lanes.py[lane] = plane ? lanes.planeHeight[lane] : cy[lane] + r[lane] * uy;
        lanes.pz[lane] = plane ? lanes.t[lane] * dz : cz[lane] + r[lane] * uz;
        lanes.ux[lane] = plane ? 0.0f : ux;
        lanes.uy[lane] = plane ? planeNormal : uy;
        lanes.uz[lane] = plane ? 0.0f : uz;
        lanes.nx[lane] = plane ? 0.0f : turn * ux;
        lanes.ny[lane] = plane ? planeNormal : turn * uy;
        lanes.nz[lane] = plane ? 0.0f : turn * uz;
        lanes.ox[lane] = lanes.px[lane] + lanes.shadowOffset[lane] * lanes.nx[lane];
        lanes.oy[lane] = lanes.py[lane] + lanes.shadowOffset[lane] * lanes.ny[lane];
        lanes.oz[lane] = lanes.pz[lane] + lanes.shadowOffset[lane] * lanes.nz[lane];
    }
}

// 0 or 1 for a float holding a whole number; exact at any magnitude.
inline float parity(float whole) {
    return whole - 2.0f * std::floor(whole * 0.5f);
}

// Whether a checker's (u, v) cell, offset by the eye's, is odd.
inline bool isOddCell(float cellU, float cellV, float eyeParity) {
    return parity(parity(cellU) + parity(cellV) + eyeParity) != 0.0f;
}

// Whether a lane's checker cell is odd. Latitude as atan(n.y, |n.xz|), as the f32 shader has it.
template <std::uint32_t W>
bool isOddChecker(const NodeLook& look, const Lanes<W>& lanes, std::uint32_t lane) {
    if (look.look == Look::PlaneChecker) {
        return isOddCell(std::floor(look.eyeCell.x + lanes.px[lane] * look.inverseSize),
                         std::floor(look.eyeCell.y + lanes.pz[lane] * look.inverseSize), look.eyeParity);
    }
    constexpr float kDegrees = 180.0f / std::numbers::pi_v<float>;
    const float ux = lanes.ux[lane], uy = lanes.uy[lane], uz = lanes.uz[lane];
    const float longitude = std::atan2(ux, uz) * kDegrees;
    const float latitude = std::atan2(uy, std::sqrt(ux * ux + uz * uz)) * kDegrees;
    return isOddCell(std::floor(longitude / look.size), std::floor(latitude / look.size), 0.0f);
}

// Each lane's colour before light (the background's and a Constant's are final: their light is 1).
template <std::uint32_t W>
void albedos(const EmbreeFloatScene& scene, Lanes<W>& lanes) {
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        glm::vec3 albedo = scene.background;
        glm::vec3 light(1.0f);
        bool lit = false;
        std::uint32_t flags = 0;
        if (lanes.node[lane] != PixelClass::kBackground) {
            const NodeLook& look = scene.looks[lanes.node[lane]];
            lit = look.look != Look::Constant;
            const bool odd = (look.look == Look::PlaneChecker || look.look == Look::SphereChecker) &&
                             isOddChecker(look, lanes, lane);
            albedo = odd ? look.color2 : look.color1;
            flags = odd ? PixelClass::kOddCheckerBit : 0;
            light = lit ? scene.ambient : light;
        }
        lanes.usesLights[lane] = lit && lanes.valid[lane] ? -1 : 0;
        lanes.flags[lane] = flags;
        lanes.albedoR[lane] = albedo.r, lanes.albedoG[lane] = albedo.g, lanes.albedoB[lane] = albedo.b;
        lanes.lightR[lane] = light.r, lanes.lightG[lane] = light.g, lanes.lightB[lane] = light.b;
    }
}

// Light `index` for every lane: Lambert's cos / r^2 where the surface faces it and no plane lies
// between (by the side each end is on, as in the reference), then the spheres asked in one
// occlusion packet of the shadow rays left (incoherent: they fan out from the tile's points).
template <std::uint32_t W>
void addLight(const EmbreeFloatScene& scene, std::size_t index, Lanes<W>& lanes) {
    const glm::vec3 light = scene.lightPositions[index];
    alignas(64) typename PacketApi<W>::Ray rays;
    alignas(64) int reaches[W];
    alignas(64) int valid[W];
    alignas(64) float irradiance[W];
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const float tx = light.x - lanes.px[lane], ty = light.y - lanes.py[lane], tz = light.z - lanes.pz[lane];
        const float distanceSquared = tx * tx + ty * ty + tz * tz;
        const float cosine =
            (lanes.nx[lane] * tx + lanes.ny[lane] * ty + lanes.nz[lane] * tz) / std::sqrt(distanceSquared);
        irradiance[lane] = cosine / distanceSquared;
        reaches[lane] = lanes.usesLights[lane] && distanceSquared > 0.0f && cosine > 0.0f ? -1 : 0;
        const float sx = light.x - lanes.ox[lane], sy = light.y - lanes.oy[lane], sz = light.z - lanes.oz[lane];
        const float distance = std::sqrt(sx * sx + sy * sy + sz * sz);
        rays.org_x[lane] = lanes.ox[lane], rays.org_y[lane] = lanes.oy[lane], rays.org_z[lane] = lanes.oz[lane];
        rays.dir_x[lane] = sx / distance, rays.dir_y[lane] = sy / distance, rays.dir_z[lane] = sz / distance;
        rays.tnear[lane] = 0.0f;
        rays.tfar[lane] = distance - lanes.shadowOffset[lane];
        rays.time[lane] = 0.0f;
        rays.mask[lane] = ~0u;
        rays.flags[lane] = 0;
    }
    for (const float height : scene.planeHeights) {
        for (std::uint32_t lane = 0; lane < W; ++lane) {
            const float from = lanes.oy[lane] - height;
            const float to = light.y - height;
            reaches[lane] = (from < 0.0f && to > 0.0f) || (from > 0.0f && to < 0.0f) ? 0 : reaches[lane];
        }
    }
    bool anyRay = false;
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        valid[lane] = reaches[lane] && rays.tfar[lane] > 0.0f ? -1 : 0;
        anyRay = anyRay || valid[lane];
    }
    if (anyRay) {
        RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
        PacketApi<W>::occluded(valid, scene.spheres.get(), &context, &rays);
    }
    const glm::vec3 power = scene.lightPowers[index];
    const std::uint32_t bit = PixelClass::litBit(std::uint32_t(index));
    for (std::uint32_t lane = 0; lane < W; ++lane) {
        const bool lit = reaches[lane] && (!valid[lane] || rays.tfar[lane] >= 0.0f);  // -inf: blocked
        const float share = lit ? irradiance[lane] : 0.0f;
        lanes.lightR[lane] += power.r * share, lanes.lightG[lane] += power.g * share;
        lanes.lightB[lane] += power.b * share;
        lanes.flags[lane] |= lit ? bit : 0u;
    }
}

// The tiles whose top row is `top`: every sample of a tile as one packet, its colours summed.
template <std::uint32_t W>
void renderPacketRow(const EmbreeFloatScene& scene, std::uint32_t top, EmbreeRender& render) {
    constexpr std::uint32_t kTileWidth = PacketApi<W>::kTileWidth;
    const std::uint32_t width = render.image.width;
    const std::uint32_t height = render.image.height;
    const float samples = float(scene.sampleOffsets.size());
    for (std::uint32_t left = 0; left < width; left += kTileWidth) {
        alignas(64) float sumR[W] = {}, sumG[W] = {}, sumB[W] = {};
        Lanes<W> lanes;
        for (std::uint32_t sample = 0; sample < scene.sampleOffsets.size(); ++sample) {
            alignas(64) typename PacketApi<W>::RayHit rays;
            cameraRays<W>(scene, left, top, sample, lanes, rays);
            RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
            PacketApi<W>::intersect(lanes.valid, scene.spheres.get(), &context, &rays);
            nearestHits<W>(scene, rays, lanes);
            surfaces<W>(scene, lanes);
            albedos<W>(scene, lanes);
            for (std::size_t light = 0; light < scene.lightPositions.size(); ++light) {
                addLight<W>(scene, light, lanes);
            }
            for (std::uint32_t lane = 0; lane < W; ++lane) {
                sumR[lane] += lanes.albedoR[lane] * lanes.lightR[lane];
                sumG[lane] += lanes.albedoG[lane] * lanes.lightG[lane];
                sumB[lane] += lanes.albedoB[lane] * lanes.lightB[lane];
            }
            for (std::uint32_t lane = 0; sample == 0 && lane < W; ++lane) {
                const std::uint32_t x = left + lane % kTileWidth, y = top + lane / kTileWidth;
                if (x < width && y < height) {
                    render.classes[std::size_t(y) * width + x] = PixelClass{lanes.node[lane], lanes.flags[lane]};
                }
            }
        }
        for (std::uint32_t lane = 0; lane < W; ++lane) {
            const std::uint32_t x = left + lane % kTileWidth, y = top + lane / kTileWidth;
            if (x < width && y < height) {
                render.image.at(x, y) = glm::vec3(sumR[lane], sumG[lane], sumB[lane]) / samples;
            }
        }
    }
}

// The same compiled for AVX2 with everything inlined, so that the lanes' loops vectorise as wide
// as an 8-ray packet where the CPU can (Embree picks its own kernels by the CPU likewise).
template <std::uint32_t W>
__attribute__((flatten, target("avx2,fma"))) void renderPacketRowAvx2(const EmbreeFloatScene& scene, std::uint32_t top,
                                                                      EmbreeRender& render) {
    renderPacketRow<W>(scene, top, render);
}

template <std::uint32_t W>
void renderImage(unsigned threadCount, const EmbreeFloatScene& scene, EmbreeRender& render) {
    constexpr std::uint32_t kTileHeight = W / PacketApi<W>::kTileWidth;
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    renderInBands(threadCount, render.image.height, kTileHeight, [&](std::uint32_t top) {
        const FlushDenormals flush;
        if (avx2) {
            renderPacketRowAvx2<W>(scene, top, render);
        } else {
            renderPacketRow<W>(scene, top, render);
        }
    });
}

bool cpuRuns(std::uint32_t width) {
    switch (width) {
        case 16:
            return __builtin_cpu_supports("avx512f");
        case 8:
            return __builtin_cpu_supports("avx2");
        default:
            return true;
    }
}

}  // namespace

std::uint32_t widestNativePacket(RTCDevice device) {
    const std::pair<std::uint32_t, RTCDeviceProperty> widths[] = {{16, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED},
                                                                  {8, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED}};
    for (const auto& [width, property] : widths) {
        if (cpuRuns(width) && rtcGetDeviceProperty(device, property) != 0) {
            return width;
        }
    }
    return 4;
}

EmbreePacketRenderer::EmbreePacketRenderer(unsigned threadCount, std::uint32_t packetWidth)
    : threadCount_(std::max(1u, threadCount)), packetWidth_(packetWidth) {
    if (packetWidth != 0 && packetWidth != 4 && packetWidth != 8 && packetWidth != 16) {
        throw std::invalid_argument("Embree packets are 4, 8 or 16 rays wide, not " + std::to_string(packetWidth));
    }
    const std::string config = "threads=" + std::to_string(threadCount_);
    device_ = rtcNewDevice(config.c_str());
    if (!device_) {
        throw std::runtime_error("Embree: rtcNewDevice failed (RTCError " + std::to_string(rtcGetDeviceError(nullptr)) +
                                 ")");
    }
    if (packetWidth_ == 0) {
        packetWidth_ = widestNativePacket(device_);
    }
}

EmbreePacketRenderer::~EmbreePacketRenderer() {
    rtcReleaseDevice(device_);
}

EmbreeRender EmbreePacketRenderer::render(const Scene& scene) const {
    EmbreeRender render;
    render.image = Image(scene.image.width, scene.image.height);
    render.classes.resize(render.image.pixels.size());
    const EmbreeFloatScene prepared(device_, scene);
    const auto start = std::chrono::steady_clock::now();
    switch (packetWidth_) {
        case 16:
            renderImage<16>(threadCount_, prepared, render);
            break;
        case 8:
            renderImage<8>(threadCount_, prepared, render);
            break;
        default:
            renderImage<4>(threadCount_, prepared, render);
            break;
    }
    render.renderMilliseconds = millisecondsSince(start);
    return render;
}

}  // namespace hexray::embree
