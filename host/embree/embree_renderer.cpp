#include "embree/embree_renderer.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>
#include <variant>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "cpu/cpu_shading.h"
#include "util/milliseconds_since.h"

namespace hexray {

namespace {

void check(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree: ") + what + " failed (RTCError " + std::to_string(error) + ")");
    }
}

// The scene as Embree and the shading below see it.
struct Prepared {
    Prepared(const Scene& scene, const glm::dvec3& eye) : scene(scene), eye(eye) {}
    Prepared(const Prepared&) = delete;
    Prepared& operator=(const Prepared&) = delete;

    const Scene& scene;
    glm::dvec3 eye;                         // world position of the camera: Embree's origin
    RTCScene spheres = nullptr;             // every sphere, camera-relative, as float
    std::vector<std::uint32_t> sphereNodes;  // Embree primID -> index into scene.nodes
    std::vector<std::uint32_t> planeNodes;   // indices into scene.nodes, in node order

    ~Prepared() {
        if (spheres) {
            rtcReleaseScene(spheres);
        }
    }
};

struct Surface {
    std::uint32_t node;
    glm::dvec3 point;           // world, on the surface (plane: snapped; sphere: reprojected)
    glm::dvec3 outwardNormal;   // plane: +Y
    glm::dvec3 facingNormal;    // turned toward the ray's side
};

// The nearest hit along the camera ray `direction` (unit, world) from the eye.
std::optional<Surface> nearestSurface(const Prepared& prepared, const glm::dvec3& direction) {
    const glm::vec3 d(direction);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // neighbouring pixels' rays
    RTCRayHit rayHit{};
    rayHit.ray.dir_x = d.x;
    rayHit.ray.dir_y = d.y;
    rayHit.ray.dir_z = d.z;
    rayHit.ray.tnear = 0.0f;
    rayHit.ray.tfar = std::numeric_limits<float>::infinity();
    rayHit.ray.mask = ~0u;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(prepared.spheres, &context, &rayHit);

    const Scene& scene = prepared.scene;
    float nearestT = std::numeric_limits<float>::infinity();
    std::uint32_t node = PixelClass::kBackground;
    if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        nearestT = rayHit.ray.tfar;
        node = prepared.sphereNodes[rayHit.hit.primID];
    }
    // Planes in float too, like everything this backend intersects; on a tie the earlier node wins.
    for (const std::uint32_t planeNode : prepared.planeNodes) {
        const double height = std::get<Plane>(scene.nodes[planeNode].geometry).height;
        const float t = float(height - prepared.eye.y) / d.y;
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
        return Surface{node, {approximate.x, plane->height, approximate.z}, up,
                       prepared.eye.y > plane->height ? up : -up};
    }
    const Sphere& sphere = std::get<Sphere>(scene.nodes[node].geometry);
    const glm::dvec3 normal = glm::normalize(approximate - sphere.center);
    return Surface{node, sphere.center + sphere.radius * normal, normal,
                   glm::dot(normal, direction) < 0.0 ? normal : -normal};
}

// Whether nothing lies between `from` and the light at `to`: planes by the side each end is on
// (as in the reference), spheres by an Embree occlusion ray ending `shortenBy` before the light.
bool isSegmentClear(const Prepared& prepared, const glm::dvec3& from, const glm::dvec3& to, double shortenBy) {
    for (const std::uint32_t planeNode : prepared.planeNodes) {
        const double height = std::get<Plane>(prepared.scene.nodes[planeNode].geometry).height;
        const double fromSide = from.y - height;
        const double toSide = to.y - height;
        if ((fromSide < 0.0 && toSide > 0.0) || (fromSide > 0.0 && toSide < 0.0)) {
            return false;
        }
    }
    const glm::dvec3 toTarget = to - from;
    const double distance = glm::length(toTarget);
    if (!(distance - shortenBy > 0.0)) {
        return true;
    }
    const glm::vec3 origin(from - prepared.eye);
    const glm::vec3 direction(toTarget / distance);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = float(distance - shortenBy);
    ray.mask = ~0u;
    rtcOccluded1(prepared.spheres, &context, &ray);
    return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when something blocks the ray
}

struct Sample {
    Color color{0.0};
    PixelClass pixelClass;
};

Sample shade(const Prepared& prepared, const std::optional<Surface>& surface) {
    const Scene& scene = prepared.scene;
    if (!surface) {
        return {scene.background, {}};
    }
    Sample sample;
    sample.pixelClass.node = surface->node;
    const Node& node = scene.nodes[surface->node];
    const Shader& shader = scene.shaders[node.shaderIndex];
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        sample.color = constant->color;
        return sample;
    }
    Color albedo{0.0};
    if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        albedo = lambert->color;
    } else {
        const CheckerShader& checker = std::get<CheckerShader>(shader);
        const glm::dvec2 uv = std::holds_alternative<Plane>(node.geometry)
                                  ? planeTextureCoordinates(surface->point)
                                  : sphereTextureCoordinates(surface->outwardNormal);
        const bool odd = checkerParity(uv.x, uv.y, checker.size) == 1;
        albedo = odd ? checker.color2 : checker.color1;
        if (odd) {
            sample.pixelClass.flags |= PixelClass::kOddCheckerBit;
        }
    }
    // Shadow rays leave a sphere from a point pushed off it by a bound on float's rounding of
    // the camera-relative coordinates Embree intersects in; a plane hit is exact and needs none.
    double offset = 0.0;
    if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
        const glm::dvec3 relative = glm::abs(sphere->center - prepared.eye);
        offset = 64.0 * FLT_EPSILON * (std::max({relative.x, relative.y, relative.z}) + sphere->radius);
    }
    Color incident = scene.ambient;
    for (std::size_t index = 0; index < scene.lights.size(); ++index) {
        const PointLight& light = scene.lights[index];
        const glm::dvec3 toLight = light.position - surface->point;
        const double distanceSquared = glm::dot(toLight, toLight);
        if (distanceSquared == 0.0) {
            continue;
        }
        const double cosTheta = glm::dot(surface->facingNormal, toLight / std::sqrt(distanceSquared));
        if (cosTheta <= 0.0 ||
            !isSegmentClear(prepared, surface->point + offset * surface->facingNormal, light.position, offset)) {
            continue;
        }
        incident += light.color * (light.intensity * cosTheta / distanceSquared);
        sample.pixelClass.flags |= PixelClass::litBit(static_cast<std::uint32_t>(index));
    }
    sample.color = albedo * incident;
    return sample;
}

}  // namespace

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

EmbreeRender EmbreeRenderer::render(const Scene& scene) const {
    EmbreeRender render;
    render.image = Image(scene.image.width, scene.image.height);
    render.classes.resize(render.image.pixels.size());

    Prepared prepared(scene, scene.camera.position);
    prepared.spheres = rtcNewScene(device_);
    check(device_, "rtcNewScene");
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (std::holds_alternative<Plane>(scene.nodes[index].geometry)) {
            prepared.planeNodes.push_back(static_cast<std::uint32_t>(index));
        } else {
            prepared.sphereNodes.push_back(static_cast<std::uint32_t>(index));
        }
    }
    if (!prepared.sphereNodes.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        check(device_, "rtcNewGeometry");
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                     RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                                     prepared.sphereNodes.size()));
        check(device_, "rtcSetNewGeometryBuffer");
        for (std::size_t i = 0; i < prepared.sphereNodes.size(); ++i) {
            const Sphere& sphere = std::get<Sphere>(scene.nodes[prepared.sphereNodes[i]].geometry);
            const glm::vec3 centre(sphere.center - prepared.eye);  // subtracted in double, then rounded once
            vertices[4 * i + 0] = centre.x;
            vertices[4 * i + 1] = centre.y;
            vertices[4 * i + 2] = centre.z;
            vertices[4 * i + 3] = float(sphere.radius);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(prepared.spheres, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(prepared.spheres);
    check(device_, "rtcCommitScene");

    const std::uint32_t width = scene.image.width;
    const std::uint32_t height = scene.image.height;
    const std::uint32_t samples = scene.image.samplesPerPixel;
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    std::atomic<std::uint32_t> nextRow{0};  // rows handed out on demand: the costly ones are not all one thread's
    const auto renderRows = [&] {
        for (std::uint32_t y = nextRow++; y < height; y = nextRow++) {
            for (std::uint32_t x = 0; x < width; ++x) {
                Color sum{0.0};
                for (std::uint32_t s = 0; s < samples; ++s) {
                    const Sample sample =
                        shade(prepared, nearestSurface(prepared, sampleDirection(sheet, scene.image, x, y, s)));
                    sum += sample.color;
                    if (s == 0) {
                        render.classes[std::size_t(y) * width + x] = sample.pixelClass;
                    }
                }
                render.image.at(x, y) = glm::vec3(sum / double(samples));
            }
        }
    };
    const auto renderStart = std::chrono::steady_clock::now();
    {
        std::vector<std::jthread> workers;
        for (unsigned worker = 1; worker < std::min<unsigned>(threadCount_, std::max(height, 1u)); ++worker) {
            workers.emplace_back(renderRows);
        }
        renderRows();
    }
    render.renderMilliseconds = millisecondsSince(renderStart);
    return render;
}

}  // namespace hexray
