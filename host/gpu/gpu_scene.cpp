#include "gpu/gpu_scene.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "gpu/precision.h"

namespace hexray::gpu {
namespace {

template <typename Real>
RealVec4<Real> toReal4(const glm::dvec3& v, double w = 0.0) {
    return RealVec4<Real>(glm::vec<4, Real>(glm::dvec4(v, w)));
}

glm::vec4 toColor(const Color& c) {
    return glm::vec4(glm::dvec4(c, 0.0));
}

// World positions and lengths as the shader sees them.
struct Placer {
    glm::dvec3 eye{0.0};
    glm::dvec3 origin{0.0};
    double scale = 1.0;
    glm::dvec3 position(const glm::dvec3& world) const { return (world - origin) / scale; }
    double length(double world) const { return world / scale; }
};

// The eye's checker cell on a plane (in world units), split into a whole part (only its
// parity matters) and a fractional part, so the shader adds only small numbers to it.
template <typename Real>
RealVec4<Real> planeCheckerPhase(const glm::dvec3& origin, double size, double placedSize) {
    const double cellX = origin.x / size;
    const double cellZ = origin.z / size;
    const double wholeX = std::floor(cellX);
    const double wholeZ = std::floor(cellZ);
    const double parity = std::fmod(std::fabs(std::fmod(wholeX, 2.0) + std::fmod(wholeZ, 2.0)), 2.0);
    return toReal4<Real>(glm::dvec3(placedSize, cellX - wholeX, cellZ - wholeZ), parity);
}

template <typename Real>
GpuNode<Real> packNode(const Node& node, const Shader& shader, const Placer& placer) {
    GpuNode<Real> packed{};
    const auto* plane = std::get_if<Plane>(&node.geometry);
    if (plane) {
        packed.kinds.x = kGeometryPlane;
        packed.geometry = toReal4<Real>(glm::dvec3(placer.position(glm::dvec3(0.0, plane->height, 0.0)).y, 0, 0));
    } else {
        const auto& sphere = std::get<Sphere>(node.geometry);
        packed.kinds.x = kGeometrySphere;
        packed.geometry = toReal4<Real>(placer.position(sphere.center), placer.length(sphere.radius));
        // (D - r)(D + r) in double: exact enough even when D - r is tiny next to D.
        const double eyeDistance = glm::length(placer.position(placer.eye) - placer.position(sphere.center));
        const double radius = placer.length(sphere.radius);
        packed.surface = toReal4<Real>(glm::dvec3((eyeDistance - radius) * (eyeDistance + radius), 0, 0));
    }
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        packed.kinds.y = kShaderConstant;
        packed.color1 = toColor(constant->color);
    } else if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        packed.kinds.y = kShaderLambert;
        packed.color1 = toColor(lambert->color);
    } else {
        const auto& checker = std::get<CheckerShader>(shader);
        packed.kinds.y = kShaderChecker;
        packed.color1 = toColor(checker.color1);
        packed.color2 = toColor(checker.color2);
        // Sphere checkers use angles, which neither move with the eye nor scale.
        packed.checker = plane ? planeCheckerPhase<Real>(placer.origin, checker.size, placer.length(checker.size))
                               : toReal4<Real>(glm::dvec3(checker.size, 0, 0));
    }
    return packed;
}

}  // namespace

bool isSmallScene(const Scene& scene) {
    return scene.nodes.size() <= kSmallSceneCapacity && scene.lights.size() <= kSmallSceneCapacity;
}

ShaderSpecialization specializationFor(const Scene& scene, std::uint32_t outputMode) {
    ShaderSpecialization specialization;
    specialization.outputMode = outputMode;
    specialization.samplesPerPixel = scene.image.samplesPerPixel;
    if (!isSmallScene(scene)) {
        return specialization;
    }
    specialization.nodeCount = std::uint32_t(scene.nodes.size());
    specialization.lightCount = std::uint32_t(scene.lights.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const std::uint32_t bit = 1u << i;
        const Shader& shader = scene.shaders[scene.nodes[i].shaderIndex];
        specialization.sphereNodes |= std::holds_alternative<Sphere>(scene.nodes[i].geometry) ? bit : 0;
        specialization.constantNodes |= std::holds_alternative<ConstantShader>(shader) ? bit : 0;
        specialization.checkerNodes |= std::holds_alternative<CheckerShader>(shader) ? bit : 0;
    }
    return specialization;
}

double placementScale(const Scene& scene) {
    const double largest = estimateConditioning(scene).largestDistance;
    return largest > 0 && std::isfinite(largest) ? std::exp2(std::round(std::log2(largest))) : 1.0;
}

template <typename Real>
GpuScene<Real> packScene(const Scene& scene, Placement placement) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    Placer placer{sheet.origin};
    if (placement == Placement::CameraRelative) {
        placer = Placer{sheet.origin, sheet.origin, placementScale(scene)};
    }

    GpuScene<Real> packed;
    GpuFrame<Real>& frame = packed.frame;
    frame.origin = toReal4<Real>(placer.position(sheet.origin));
    // Directions: the sheet is at distance 1 whatever the scale.
    frame.sheetTopLeft = toReal4<Real>(sheet.topLeft);
    frame.sheetRight = toReal4<Real>(sheet.right);
    frame.sheetDown = toReal4<Real>(sheet.down);
    frame.background = toColor(scene.background);
    frame.ambient = toColor(scene.ambient);
    frame.imageSize = glm::uvec2(scene.image.width, scene.image.height);
    frame.samplingOffset = float(samplingOffset(scene.image.sampling));
    frame.nodeCount = std::uint32_t(scene.nodes.size());
    frame.lightCount = std::uint32_t(scene.lights.size());

    for (const Node& node : scene.nodes) {
        packed.nodes.push_back(packNode<Real>(node, scene.shaders[node.shaderIndex], placer));
    }
    // Irradiance falls off as 1/r^2: lengths divided by s need intensities divided by s^2.
    const double powerScale = 1.0 / (placer.scale * placer.scale);
    for (const PointLight& light : scene.lights) {
        packed.lights.push_back({toReal4<Real>(placer.position(light.position)),
                                 toColor(light.color * (light.intensity * powerScale))});
    }
    return packed;
}

template GpuScene<float> packScene<float>(const Scene&, Placement);
template GpuScene<double> packScene<double>(const Scene&, Placement);

}  // namespace hexray::gpu
