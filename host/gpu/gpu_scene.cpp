#include "gpu/gpu_scene.h"

#include <cmath>

#include "camera/camera.h"

namespace hexray::gpu {
namespace {

glm::vec4 toVec4(const glm::dvec3& v, double w = 0.0) {
    return glm::vec4(glm::dvec4(v, w));
}

// The eye's checker cell on a plane, split into a whole part (only its parity matters) and a
// fractional part, so the shader adds only small camera-relative numbers to it.
glm::vec4 planeCheckerPhase(const glm::dvec3& eye, double size) {
    const double cellX = eye.x / size;
    const double cellZ = eye.z / size;
    const double wholeX = std::floor(cellX);
    const double wholeZ = std::floor(cellZ);
    const double parity = std::fmod(std::fabs(std::fmod(wholeX, 2.0) + std::fmod(wholeZ, 2.0)), 2.0);
    return glm::vec4(float(size), float(cellX - wholeX), float(cellZ - wholeZ), float(parity));
}

GpuNode packNode(const Node& node, const Shader& shader, const glm::dvec3& eye) {
    GpuNode packed{};
    const auto* plane = std::get_if<Plane>(&node.geometry);
    if (plane) {
        packed.kinds.x = kGeometryPlane;
        packed.geometry = glm::vec4(float(plane->height - eye.y), 0.0f, 0.0f, 0.0f);
    } else {
        const auto& sphere = std::get<Sphere>(node.geometry);
        packed.kinds.x = kGeometrySphere;
        packed.geometry = toVec4(sphere.center - eye, sphere.radius);
    }
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        packed.kinds.y = kShaderConstant;
        packed.color1 = toVec4(constant->color);
    } else if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        packed.kinds.y = kShaderLambert;
        packed.color1 = toVec4(lambert->color);
    } else {
        const auto& checker = std::get<CheckerShader>(shader);
        packed.kinds.y = kShaderChecker;
        packed.color1 = toVec4(checker.color1);
        packed.color2 = toVec4(checker.color2);
        // Sphere checkers use angles, which do not move with the eye.
        packed.checker = plane ? planeCheckerPhase(eye, checker.size) : glm::vec4(float(checker.size), 0, 0, 0);
    }
    return packed;
}

}  // namespace

GpuScene packScene(const Scene& scene) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const glm::dvec3 eye = sheet.origin;

    GpuScene packed;
    GpuFrame& frame = packed.frame;
    frame.sheetTopLeft = toVec4(sheet.topLeft);
    frame.sheetRight = toVec4(sheet.right);
    frame.sheetDown = toVec4(sheet.down);
    frame.background = toVec4(scene.background);
    frame.ambient = toVec4(scene.ambient);
    frame.imageSize = glm::uvec2(scene.image.width, scene.image.height);
    frame.samplingOffset = float(samplingOffset(scene.image.sampling));
    frame.nodeCount = std::uint32_t(scene.nodes.size());
    frame.lightCount = std::uint32_t(scene.lights.size());

    for (const Node& node : scene.nodes) {
        packed.nodes.push_back(packNode(node, scene.shaders[node.shaderIndex], eye));
    }
    for (const PointLight& light : scene.lights) {
        packed.lights.push_back({toVec4(light.position - eye), toVec4(light.color * light.intensity)});
    }
    return packed;
}

}  // namespace hexray::gpu
