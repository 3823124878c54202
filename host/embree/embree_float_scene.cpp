#include "embree/embree_float_scene.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include <glm/common.hpp>

#include "camera/camera.h"
#include "embree/embree_calls.h"

namespace hexray::inline embree {
namespace {

// Longitude and latitude lie within (-180, 180] and [-90, 90] degrees: any checker size from a
// full turn up gives the cells of a full turn, which float holds.
constexpr double kSphereCheckerFullTurn = 360.0;

NodeLook lookOf(const Node& node, const Shader& shader, const glm::dvec3& eye) {
    NodeLook look;
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        look.color1 = glm::vec3(constant->color);
        return look;
    }
    if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        look.look = Look::Lambert;
        look.color1 = glm::vec3(lambert->color);
        return look;
    }
    const auto& checker = std::get<CheckerShader>(shader);
    look.color1 = glm::vec3(checker.color1);
    look.color2 = glm::vec3(checker.color2);
    if (std::holds_alternative<Plane>(node.geometry)) {
        look.look = Look::PlaneChecker;
        look.size = float(checker.size);
        look.inverseSize = float(1.0 / checker.size);
        const glm::dvec2 cell(eye.x / checker.size, eye.z / checker.size);
        const glm::dvec2 whole = glm::floor(cell);
        look.eyeCell = glm::vec2(cell - whole);
        look.eyeParity = float(std::fmod(std::fabs(std::fmod(whole.x, 2.0) + std::fmod(whole.y, 2.0)), 2.0));
    } else {
        look.look = Look::SphereChecker;
        look.size = float(std::min(checker.size, kSphereCheckerFullTurn));
        look.inverseSize = 1.0f / look.size;
    }
    return look;
}

}  // namespace

EmbreeFloatScene::EmbreeFloatScene(RTCDevice device, const Scene& scene)
    : spheres(rtcNewScene(device), &rtcReleaseScene) {
    checkEmbree(device, "rtcNewScene");
    const glm::dvec3 eye = scene.camera.position;
    std::vector<std::uint32_t> sphereNodeList;
    for (std::uint32_t index = 0; index < scene.nodes.size(); ++index) {
        const Node& node = scene.nodes[index];
        looks.push_back(lookOf(node, scene.shaders[node.shaderIndex], eye));
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            planeHeights.push_back(float(plane->height - eye.y));
            planeNodes.push_back(index);
        } else {
            sphereNodeList.push_back(index);
        }
    }
    addSpheres(device, scene, sphereNodeList);
    for (const PointLight& light : scene.lights) {
        lightPositions.emplace_back(light.position - eye);
        lightPowers.emplace_back(light.color * light.intensity);
    }
    ambient = glm::vec3(scene.ambient);
    background = glm::vec3(scene.background);
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    topLeft = glm::vec3(sheet.topLeft);
    right = glm::vec3(sheet.right);
    down = glm::vec3(sheet.down);
    for (std::uint32_t sample = 0; sample < scene.image.samplesPerPixel; ++sample) {
        sampleOffsets.emplace_back(sampleOffset(sample, scene.image.samplesPerPixel, scene.image.sampling));
    }
    width = float(scene.image.width);
    height = float(scene.image.height);
}

void EmbreeFloatScene::addSpheres(RTCDevice device, const Scene& scene, const std::vector<std::uint32_t>& nodes) {
    // A static scene traced many times: the best tree Embree builds, without its slower robust mode.
    rtcSetSceneBuildQuality(spheres.get(), RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(spheres.get(), RTC_SCENE_FLAG_NONE);
    if (!nodes.empty()) {
        const std::unique_ptr<RTCGeometryTy, decltype(&rtcReleaseGeometry)> geometry(
            rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT), &rtcReleaseGeometry);
        checkEmbree(device, "rtcNewGeometry");
        rtcSetGeometryBuildQuality(geometry.get(), RTC_BUILD_QUALITY_HIGH);
        auto* vertices = static_cast<glm::vec4*>(rtcSetNewGeometryBuffer(
            geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(glm::vec4), nodes.size()));
        checkEmbree(device, "rtcSetNewGeometryBuffer");
        const glm::dvec3 eye = scene.camera.position;
        for (const std::uint32_t node : nodes) {
            const Sphere& sphere = std::get<Sphere>(scene.nodes[node].geometry);
            const glm::dvec3 centre = sphere.center - eye;  // subtracted in double, rounded once
            const glm::vec4 packed(glm::vec3(centre), float(sphere.radius));
            vertices[sphereData.size()] = packed;
            sphereData.push_back(packed);
            sphereNodes.push_back(node);
            // Past a bound on float's rounding of the reprojected point, so no shadow ray hits its
            // own sphere where it starts.
            const glm::dvec3 relative = glm::abs(centre);
            shadowOffsets.push_back(
                float(64.0 * FLT_EPSILON * (std::max({relative.x, relative.y, relative.z}) + sphere.radius)));
        }
        rtcCommitGeometry(geometry.get());
        rtcAttachGeometry(spheres.get(), geometry.get());  // the scene keeps its own reference
    }
    rtcCommitScene(spheres.get());
    checkEmbree(device, "rtcCommitScene");
}

}  // namespace hexray::embree
