#include "embree/embree_renderer.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "cpu/cpu_shading.h"
#include "embree/embree_calls.h"
#include "embree/render_in_bands.h"
#include "util/milliseconds_since.h"

namespace hexray::inline embree {

namespace {

// The scene as Embree and the shading below see it.
class Prepared {
public:
    Prepared(RTCDevice device, const Scene& scene)
        : scene(scene), eye(scene.camera.position), spheres(rtcNewScene(device), &rtcReleaseScene) {
        checkEmbree(device, "rtcNewScene");
        for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
            auto& list = std::holds_alternative<Plane>(scene.nodes[index].geometry) ? planeNodes : sphereNodes;
            list.push_back(static_cast<std::uint32_t>(index));
        }
        if (!sphereNodes.empty()) {
            attachSpheres(device);
        }
        rtcCommitScene(spheres.get());
        checkEmbree(device, "rtcCommitScene");
    }

    const Scene& scene;
    glm::dvec3 eye;  // world position of the camera: Embree's origin
    // Every sphere, camera-relative, as float.
    const std::unique_ptr<RTCSceneTy, decltype(&rtcReleaseScene)> spheres;
    std::vector<std::uint32_t> sphereNodes;  // Embree primID -> index into scene.nodes
    std::vector<std::uint32_t> planeNodes;   // indices into scene.nodes, in node order

private:
    void attachSpheres(RTCDevice device) {
        const std::unique_ptr<RTCGeometryTy, decltype(&rtcReleaseGeometry)> geometry(
            rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT), &rtcReleaseGeometry);
        checkEmbree(device, "rtcNewGeometry");
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), sphereNodes.size()));
        checkEmbree(device, "rtcSetNewGeometryBuffer");
        for (std::size_t i = 0; i < sphereNodes.size(); ++i) {
            const Sphere& sphere = std::get<Sphere>(scene.nodes[sphereNodes[i]].geometry);
            const glm::vec3 centre(sphere.center - eye);  // subtracted in double, then rounded once
            vertices[4 * i + 0] = centre.x;
            vertices[4 * i + 1] = centre.y;
            vertices[4 * i + 2] = centre.z;
            vertices[4 * i + 3] = float(sphere.radius);
        }
        rtcCommitGeometry(geometry.get());
        rtcAttachGeometry(spheres.get(), geometry.get());  // the scene keeps its own reference
    }
};

struct Surface {
    std::uint32_t node;
    glm::dvec3 point;          // world, on the surface (plane: snapped; sphere: reprojected)
    glm::dvec3 outwardNormal;  // plane: +Y
    glm::dvec3 facingNormal;   // turned toward the ray's side
};

// The nearest hit along the camera ray `direction` (unit, world) from the eye, given the
// nearest sphere Embree found along it (t, scene node), if any.
std::optional<Surface> nearestSurface(const Prepared& prepared, const glm::dvec3& direction,
                                      std::optional<std::pair<float, std::uint32_t>> sphereHit) {
    const Scene& scene = prepared.scene;
    float nearestT = std::numeric_limits<float>::infinity();
    std::uint32_t node = PixelClass::kBackground;
    if (sphereHit) {
        std::tie(nearestT, node) = *sphereHit;
    }
    // Planes in float too, like everything this backend intersects; on a tie the earlier node wins.
    for (const std::uint32_t planeNode : prepared.planeNodes) {
        const double height = std::get<Plane>(scene.nodes[planeNode].geometry).height;
        const float t = float(height - prepared.eye.y) / float(direction.y);
        if (t > 0.0f && t < std::numeric_limits<float>::infinity() &&
            (t < nearestT || (t == nearestT && planeNode < node))) {
            nearestT = t;
            node = planeNode;
        }
    }
    if (node == PixelClass::kBackground) {
        return std::nullopt;
    }
    const glm::dvec3 approximate = prepared.eye + double(nearestT) * direction;
    if (const auto* plane = std::get_if<Plane>(&scene.nodes[node].geometry)) {
        const glm::dvec3 up(0.0, 1.0, 0.0);
        return Surface{
            node, {approximate.x, plane->height, approximate.z}, up, prepared.eye.y > plane->height ? up : -up};
    }
    const Sphere& sphere = std::get<Sphere>(scene.nodes[node].geometry);
    const glm::dvec3 normal = glm::normalize(approximate - sphere.center);
    return Surface{node, sphere.center + sphere.radius * normal, normal,
                   glm::dot(normal, direction) < 0.0 ? normal : -normal};
}

// A segment toward a light that only an Embree occlusion ray can clear: camera-relative, float.
struct ShadowRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float length;
};

// Whether a light can reach a point, before any sphere is asked.
struct LightReach {
    bool blocked = false;                // facing away, or a plane between
    Color contribution{0.0};             // added when it reaches
    std::optional<ShadowRay> shadowRay;  // absent: nothing left to ask

    static LightReach none() {
        LightReach reach;
        reach.blocked = true;
        return reach;
    }
};

// Whether nothing lies between `from` and the light at `to`, as far as the planes tell (by the
// side each end is on, as in the reference), and the occlusion ray that asks the spheres for
// the segment ending `shortenBy` before the light.
LightReach segmentToLight(const Prepared& prepared, const glm::dvec3& from, const glm::dvec3& to, double shortenBy) {
    LightReach reach;
    for (const std::uint32_t planeNode : prepared.planeNodes) {
        const double height = std::get<Plane>(prepared.scene.nodes[planeNode].geometry).height;
        const double fromSide = from.y - height;
        const double toSide = to.y - height;
        if ((fromSide < 0.0 && toSide > 0.0) || (fromSide > 0.0 && toSide < 0.0)) {
            return LightReach::none();
        }
    }
    const glm::dvec3 toTarget = to - from;
    const double distance = glm::length(toTarget);
    if (distance - shortenBy > 0.0) {
        reach.shadowRay =
            ShadowRay{glm::vec3(from - prepared.eye), glm::vec3(toTarget / distance), float(distance - shortenBy)};
    }
    return reach;
}

struct Sample {
    Color color{0.0};
    PixelClass pixelClass;
};

// One sample's shading, in steps, so that packets can trace the shadow rays of several
// samples at once: start it, let each light in whose reach is confirmed, finish it.
class SampleShading {
public:
    SampleShading(const Prepared& prepared, const std::optional<Surface>& surface)
        : prepared_(prepared), surface_(surface.value_or(Surface{})) {
        const Scene& scene = prepared.scene;
        if (!surface) {
            sample_.color = scene.background;
            return;
        }
        sample_.pixelClass.node = surface->node;
        const Node& node = scene.nodes[surface->node];
        const Shader& shader = scene.shaders[node.shaderIndex];
        if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
            sample_.color = constant->color;
            return;
        }
        usesLights_ = true;
        incident_ = scene.ambient;
        if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
            albedo_ = lambert->color;
        } else {
            const CheckerShader& checker = std::get<CheckerShader>(shader);
            const glm::dvec2 uv = std::holds_alternative<Plane>(node.geometry)
                                      ? planeTextureCoordinates(surface->point)
                                      : sphereTextureCoordinates(surface->outwardNormal);
            const bool odd = checkerParity(uv.x, uv.y, checker.size) == 1;
            albedo_ = odd ? checker.color2 : checker.color1;
            if (odd) {
                sample_.pixelClass.flags |= PixelClass::kOddCheckerBit;
            }
        }
        // Shadow rays leave a sphere from a point pushed off it by a bound on float's rounding of
        // the camera-relative coordinates Embree intersects in; a plane hit is exact and needs none.
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            const glm::dvec3 relative = glm::abs(sphere->center - prepared.eye);
            offset_ = 64.0 * FLT_EPSILON * (std::max({relative.x, relative.y, relative.z}) + sphere->radius);
        }
    }

    bool usesLights() const { return usesLights_; }

    // Light `index`'s reach; call only when usesLights().
    LightReach reach(std::size_t index) const {
        const PointLight& light = prepared_.scene.lights[index];
        const glm::dvec3 toLight = light.position - surface_.point;
        const double distanceSquared = glm::dot(toLight, toLight);
        if (distanceSquared == 0.0) {
            return LightReach::none();
        }
        const double cosTheta = glm::dot(surface_.facingNormal, toLight / std::sqrt(distanceSquared));
        if (cosTheta <= 0.0) {
            return LightReach::none();
        }
        LightReach reach =
            segmentToLight(prepared_, surface_.point + offset_ * surface_.facingNormal, light.position, offset_);
        reach.contribution = light.color * (light.intensity * cosTheta / distanceSquared);
        return reach;
    }

    void addLight(std::size_t index, const Color& contribution) {
        incident_ += contribution;
        sample_.pixelClass.flags |= PixelClass::litBit(static_cast<std::uint32_t>(index));
    }

    Sample finish() const {
        if (!usesLights_) {
            return sample_;
        }
        return Sample{albedo_ * incident_, sample_.pixelClass};
    }

private:
    const Prepared& prepared_;
    Surface surface_;  // meaningful when usesLights()
    Sample sample_;
    bool usesLights_ = false;
    Color albedo_{0.0};
    Color incident_{0.0};
    double offset_ = 0.0;
};

// ---------------------------------------------------------------- one ray at a time

bool isClear(const Prepared& prepared, const ShadowRay& shadowRay) {
    RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
    RTCRay ray{};
    ray.org_x = shadowRay.origin.x;
    ray.org_y = shadowRay.origin.y;
    ray.org_z = shadowRay.origin.z;
    ray.dir_x = shadowRay.direction.x;
    ray.dir_y = shadowRay.direction.y;
    ray.dir_z = shadowRay.direction.z;
    ray.tnear = 0.0f;
    ray.tfar = shadowRay.length;
    ray.mask = ~0u;
    rtcOccluded1(prepared.spheres.get(), &context, &ray);
    return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when something blocks the ray
}

Sample traceSingleRay(const Prepared& prepared, const glm::dvec3& direction) {
    const glm::vec3 d(direction);
    RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);  // neighbouring pixels' rays
    RTCRayHit rayHit{};
    rayHit.ray.dir_x = d.x;
    rayHit.ray.dir_y = d.y;
    rayHit.ray.dir_z = d.z;
    rayHit.ray.tnear = 0.0f;
    rayHit.ray.tfar = std::numeric_limits<float>::infinity();
    rayHit.ray.mask = ~0u;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(prepared.spheres.get(), &context, &rayHit);

    std::optional<std::pair<float, std::uint32_t>> sphereHit;
    if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        sphereHit.emplace(rayHit.ray.tfar, prepared.sphereNodes[rayHit.hit.primID]);
    }
    SampleShading shading(prepared, nearestSurface(prepared, direction, sphereHit));
    if (shading.usesLights()) {
        for (std::size_t light = 0; light < prepared.scene.lights.size(); ++light) {
            const LightReach reach = shading.reach(light);
            if (!reach.blocked && (!reach.shadowRay || isClear(prepared, *reach.shadowRay))) {
                shading.addLight(light, reach.contribution);
            }
        }
    }
    return shading.finish();
}

// ---------------------------------------------------------------- packets

// A packet's pixels: a tile kTileWidth wide, kTileHeight tall; lane = row * kTileWidth + column.
constexpr std::uint32_t kTileWidth = 4;
constexpr std::uint32_t kTileHeight = kEmbreePacketSize / kTileWidth;
constexpr int kLanes = int(kEmbreePacketSize);

using RayPacket = RTCRay8;
using RayHitPacket = RTCRayHit8;
static_assert(sizeof(RayPacket::tfar) == kEmbreePacketSize * sizeof(float));

// Embree's valid masks: -1 for a lane to trace, 0 for one to skip.
using LaneMask = std::array<int, kEmbreePacketSize>;

// One sample of each pixel of a tile (lanes outside the image are left out).
class TilePacket {
public:
    TilePacket(const Prepared& prepared, const LaneMask& inImage,
               const std::array<glm::dvec3, kEmbreePacketSize>& directions)
        : prepared_(prepared), inImage_(inImage), directions_(directions) {}

    // Traces the camera rays, shades every lane, and writes each lane's sample to `out`.
    void trace(std::array<Sample, kEmbreePacketSize>& out) {
        alignas(64) RayHitPacket packet{};
        for (int lane = 0; lane < kLanes; ++lane) {
            const glm::vec3 d(directions_[lane]);
            packet.ray.dir_x[lane] = d.x;
            packet.ray.dir_y[lane] = d.y;
            packet.ray.dir_z[lane] = d.z;
            packet.ray.tfar[lane] = std::numeric_limits<float>::infinity();
            packet.ray.mask[lane] = ~0u;
            packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
        }
        RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
        alignas(64) const LaneMask valid = inImage_;
        rtcIntersect8(valid.data(), prepared_.spheres.get(), &context, &packet);

        std::array<std::optional<SampleShading>, kEmbreePacketSize> shadings;
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!inImage_[lane]) {
                continue;
            }
            std::optional<std::pair<float, std::uint32_t>> sphereHit;
            if (packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
                sphereHit.emplace(packet.ray.tfar[lane], prepared_.sphereNodes[packet.hit.primID[lane]]);
            }
            shadings[lane].emplace(prepared_, nearestSurface(prepared_, directions_[lane], sphereHit));
        }
        for (std::size_t light = 0; light < prepared_.scene.lights.size(); ++light) {
            shadeLight(light, shadings);
        }
        for (int lane = 0; lane < kLanes; ++lane) {
            if (shadings[lane]) {
                out[lane] = shadings[lane]->finish();
            }
        }
    }

private:
    // Light `light` for every lane: the shadow rays that remain after the planes, as one packet.
    void shadeLight(std::size_t light, std::array<std::optional<SampleShading>, kEmbreePacketSize>& shadings) const {
        std::array<LightReach, kEmbreePacketSize> reaches;
        alignas(64) LaneMask valid{};
        alignas(64) RayPacket packet{};
        bool anyRay = false;
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!shadings[lane] || !shadings[lane]->usesLights()) {
                reaches[lane] = LightReach::none();
                continue;
            }
            reaches[lane] = shadings[lane]->reach(light);
            if (reaches[lane].blocked || !reaches[lane].shadowRay) {
                continue;
            }
            const ShadowRay& ray = *reaches[lane].shadowRay;
            packet.org_x[lane] = ray.origin.x;
            packet.org_y[lane] = ray.origin.y;
            packet.org_z[lane] = ray.origin.z;
            packet.dir_x[lane] = ray.direction.x;
            packet.dir_y[lane] = ray.direction.y;
            packet.dir_z[lane] = ray.direction.z;
            packet.tfar[lane] = ray.length;
            packet.mask[lane] = ~0u;
            valid[lane] = -1;
            anyRay = true;
        }
        if (anyRay) {
            // The rays of neighbouring points toward one light.
            RTCIntersectContext context = intersectContext(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
            rtcOccluded8(valid.data(), prepared_.spheres.get(), &context, &packet);
        }
        for (int lane = 0; lane < kLanes; ++lane) {
            const bool clear = !valid[lane] || packet.tfar[lane] >= 0.0f;  // -inf: something blocks it
            if (!reaches[lane].blocked && clear) {
                shadings[lane]->addLight(light, reaches[lane].contribution);
            }
        }
    }

    const Prepared& prepared_;
    const LaneMask& inImage_;
    const std::array<glm::dvec3, kEmbreePacketSize>& directions_;
};

// ---------------------------------------------------------------- the image

// A pixel's samples, averaged, and its first sample's class.
class PixelSum {
public:
    void add(const Sample& sample) {
        if (count_ == 0) {
            pixelClass_ = sample.pixelClass;
        }
        sum_ += sample.color;
        ++count_;
    }
    void store(std::uint32_t x, std::uint32_t y, EmbreeRender& render) const {
        render.image.at(x, y) = glm::vec3(sum_ / double(count_));
        render.classes[std::size_t(y) * render.image.width + x] = pixelClass_;
    }

private:
    Color sum_{0.0};
    std::uint32_t count_ = 0;
    PixelClass pixelClass_;
};

// The tiles whose top row is `top`, every sample of each as one packet.
void renderTileRow(const Prepared& prepared, const PixelSheet& sheet, std::uint32_t top, EmbreeRender& render) {
    const ImageSettings& image = prepared.scene.image;
    for (std::uint32_t left = 0; left < image.width; left += kTileWidth) {
        alignas(64) LaneMask inImage{};
        std::array<PixelSum, kEmbreePacketSize> pixels;
        const auto xOf = [&](int lane) { return left + std::uint32_t(lane) % kTileWidth; };
        const auto yOf = [&](int lane) { return top + std::uint32_t(lane) / kTileWidth; };
        for (int lane = 0; lane < kLanes; ++lane) {
            inImage[lane] = xOf(lane) < image.width && yOf(lane) < image.height ? -1 : 0;
        }
        for (std::uint32_t s = 0; s < image.samplesPerPixel; ++s) {
            std::array<glm::dvec3, kEmbreePacketSize> directions{};
            for (int lane = 0; lane < kLanes; ++lane) {
                if (inImage[lane]) {
                    directions[lane] = sampleDirection(sheet, image, xOf(lane), yOf(lane), s);
                }
            }
            std::array<Sample, kEmbreePacketSize> samples;
            TilePacket(prepared, inImage, directions).trace(samples);
            for (int lane = 0; lane < kLanes; ++lane) {
                pixels[lane].add(samples[lane]);
            }
        }
        for (int lane = 0; lane < kLanes; ++lane) {
            if (inImage[lane]) {
                pixels[lane].store(xOf(lane), yOf(lane), render);
            }
        }
    }
}

}  // namespace

std::string tracingName(EmbreeTracing tracing) {
    return tracing == EmbreeTracing::Packets ? std::to_string(kEmbreePacketSize) + "-ray packets" : "single rays";
}

EmbreeRenderer::EmbreeRenderer(unsigned threadCount) : threadCount_(std::max(1u, threadCount)) {
    const std::string config = "threads=" + std::to_string(threadCount_);
    device_ = rtcNewDevice(config.c_str());
    if (!device_) {
        throw std::runtime_error("Embree: rtcNewDevice failed (RTCError " + std::to_string(rtcGetDeviceError(nullptr)) +
                                 ")");
    }
}

EmbreeRenderer::~EmbreeRenderer() {
    rtcReleaseDevice(device_);
}

std::string EmbreeRenderer::version() const {
    const long long version = rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_VERSION);  // e.g. 31305
    return "Embree " + std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." +
           std::to_string(version % 100);
}

EmbreeRender EmbreeRenderer::render(const Scene& scene, EmbreeTracing tracing) const {
    EmbreeRender render;
    render.image = Image(scene.image.width, scene.image.height);
    render.classes.resize(render.image.pixels.size());
    const Prepared prepared(device_, scene);
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const auto renderStart = std::chrono::steady_clock::now();
    if (tracing == EmbreeTracing::Packets) {
        renderInBands(threadCount_, scene.image.height, kTileHeight,
                      [&](std::uint32_t top) { renderTileRow(prepared, sheet, top, render); });
    } else {
        renderInBands(threadCount_, scene.image.height, 1, [&](std::uint32_t y) {
            for (std::uint32_t x = 0; x < scene.image.width; ++x) {
                PixelSum pixel;
                for (std::uint32_t s = 0; s < scene.image.samplesPerPixel; ++s) {
                    pixel.add(traceSingleRay(prepared, sampleDirection(sheet, scene.image, x, y, s)));
                }
                pixel.store(x, y, render);
            }
        });
    }
    render.renderMilliseconds = millisecondsSince(renderStart);
    return render;
}

}  // namespace hexray::embree
