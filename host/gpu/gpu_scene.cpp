#include "gpu/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "precision/precision.h"
#include "util/parallel_parts.h"

namespace hexray::inline gpu {
namespace {

template <typename Real>
RealVec4<Real> toReal4(const glm::dvec3& v, double w = 0.0) {
    return RealVec4<Real>(glm::vec<4, Real>(glm::dvec4(v, w)));
}

glm::vec4 toColor(const Color& c) {
    return glm::vec4(glm::dvec4(c, 0.0));
}

// The eye's power with respect to a sphere, |f|^2 - r^2 for f = eye - centre, to about one rounding
// of the result: each square split exactly into two doubles (fma), the eight parts summed with
// their rounding errors carried (TwoSum). Plain double would lose the small power of an eye close
// to a large sphere (or on one) to cancellation against |f|^2.
double eyePower(const glm::dvec3& f, double radius) {
    double sum = 0.0;
    double carried = 0.0;
    const auto add = [&](double x) {
        const double total = sum + x;
        const double part = total - sum;
        carried += (sum - (total - part)) + (x - part);
        sum = total;
    };
    const auto addSquare = [&](double x, double sign) {
        const double square = x * x;
        add(sign * square);
        add(sign * std::fma(x, x, -square));
    };
    addSquare(f.x, 1.0);
    addSquare(f.y, 1.0);
    addSquare(f.z, 1.0);
    addSquare(radius, -1.0);
    return sum + carried;
}

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

// Longitude is in (-180, 180] degrees and latitude in [-90, 90], so an angle x over a size of at
// least 360 lies in (-0.5, 0.5]: its cell is -1 below 0 and 0 from 0 on, whatever the size. A
// larger size (up to 1e50, beyond float's 3.4e38) gives exactly the cells of 360.
constexpr double kSphereCheckerFullTurn = 360.0;

template <typename Real>
GpuNode<Real> packNode(const Node& node, const Placement& placement, const glm::dvec3& eye, std::uint32_t look) {
    GpuNode<Real> packed{};
    packed.look = look;
    if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
        packed.geometryKind = GEOMETRY_PLANE;
        packed.geometry = toReal4<Real>(glm::dvec3(placement.position(glm::dvec3(0.0, plane->height, 0.0)).y, 0, 0));
    } else {
        const auto& sphere = std::get<Sphere>(node.geometry);
        packed.geometryKind = GEOMETRY_SPHERE;
        packed.geometry = toReal4<Real>(placement.position(sphere.center), placement.length(sphere.radius));
        const glm::dvec3 fromCenter = placement.position(eye) - placement.position(sphere.center);
        packed.eyePower = Real(eyePower(fromCenter, placement.length(sphere.radius)));
    }
    return packed;
}

template <typename Real>
GpuLook<Real> packLook(const Shader& shader, bool sphere, const Placement& placement) {
    GpuLook<Real> packed{};
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        packed.shaderKind = SHADER_CONSTANT;
        packed.color1 = glm::vec3(constant->color);
    } else if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        packed.shaderKind = SHADER_LAMBERT;
        packed.color1 = glm::vec3(lambert->color);
    } else {
        const auto& checker = std::get<CheckerShader>(shader);
        packed.shaderKind = SHADER_CHECKER;
        packed.color1 = glm::vec3(checker.color1);
        packed.color2 = toColor(checker.color2);
        // Sphere checkers use angles, which neither move with the eye nor scale; capped (exactly:
        // see kSphereCheckerFullTurn) so that float holds the size. Plane sizes are lengths, which
        // the placement brings within float's range.
        packed.checker = sphere
                             ? toReal4<Real>(glm::dvec3(std::min(checker.size, kSphereCheckerFullTurn), 0, 0))
                             : planeCheckerPhase<Real>(placement.origin, checker.size, placement.length(checker.size));
    }
    return packed;
}

}  // namespace

template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement, NodePacking nodes) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));

    GpuScene<Real> packed;
    GpuFrame<Real>& frame = packed.frame;
    frame.origin = toReal4<Real>(placement.position(sheet.origin));
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
    // The planes, gathered in one pass: the frame counts them, and each light asks whether one may shadow it.
    std::vector<Plane> planes;
    for (const Node& node : scene.nodes) {
        if (const auto* plane = std::get_if<Plane>(&node.geometry)) {
            planes.push_back(*plane);
        }
    }
    frame.planeCount = std::uint32_t(planes.size());

    packed.lookIndex = LookIndex(scene);
    for (std::size_t l = 0; l < packed.lookIndex.size(); ++l) {
        packed.looks.push_back(packLook<Real>(scene.shaders[packed.lookIndex.shaderIndex(l)],
                                              packed.lookIndex.showsSpheres(l), placement));
    }
    if (nodes == NodePacking::Now) {
        packed.nodes.resize(scene.nodes.size());
        packNodesInto<Real>(scene, placement, packed.lookIndex, reinterpret_cast<std::byte*>(packed.nodes.data()));
    }
    // Irradiance falls off as 1/r^2: lengths divided by s need intensities divided by s^2.
    const double powerScale = 1.0 / (placement.scale * placement.scale);
    packed.lights.reserve(scene.lights.size());
    for (const PointLight& light : scene.lights) {
        const double hidden = isLightHiddenFromView(scene, light) ? 1.0 : 0.0;
        const bool planeMayShadowIt = std::ranges::any_of(
            planes, [&](const Plane& plane) { return planeMayShadow(plane, scene.camera.position, light.position); });
        const double planesClear = planeMayShadowIt ? 0.0 : 1.0;
        packed.lights.push_back({toReal4<Real>(placement.position(light.position), hidden),
                                 toReal4<Real>(light.color * (light.intensity * powerScale), planesClear)});
    }
    return packed;
}

template GpuScene<float> packScene<float>(const Scene&, const Placement&, NodePacking);
template GpuScene<double> packScene<double>(const Scene&, const Placement&, NodePacking);

LookIndex::LookIndex(const Scene& scene) : lookOfSlot_(2 * scene.shaders.size(), 0) {
    std::vector<bool> seen(lookOfSlot_.size(), false);
    for (const Node& node : scene.nodes) {
        const std::size_t at = slot(node.shaderIndex, isSphere(node));
        if (!seen[at]) {
            seen[at] = true;
            lookOfSlot_[at] = std::uint32_t(looks_.size());
            looks_.push_back({node.shaderIndex, isSphere(node)});
        }
    }
}

template <typename Real>
void packNodesInto(const Scene& scene, const Placement& placement, const LookIndex& looks, std::byte* out) {
    const glm::dvec3 eye = makePixelSheet(scene.camera, sheetAspect(scene)).origin;
    runAcrossCores(scene.nodes.size(), kNodesPerPart, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            const GpuNode<Real> packed = packNode<Real>(scene.nodes[i], placement, eye, looks.of(scene.nodes[i]));
            std::memcpy(out + i * sizeof packed, &packed, sizeof packed);
        }
    });
}

template void packNodesInto<float>(const Scene&, const Placement&, const LookIndex&, std::byte*);
template void packNodesInto<double>(const Scene&, const Placement&, const LookIndex&, std::byte*);

template <typename Real>
void packCandidateSpheresInto(const Scene& scene, const Placement& placement,
                              std::span<const std::uint32_t> sphereNodes, const LookIndex& looks, std::byte* out) {
    const glm::dvec3 eye = makePixelSheet(scene.camera, sheetAspect(scene)).origin;
    // The records lie in space's order, the nodes in the file's: each node is read in turn and its
    // record written where it goes, since scattered writes wait on nothing and scattered reads do.
    constexpr std::uint32_t kNoRecord = std::numeric_limits<std::uint32_t>::max();
    std::byte* const geometry = out;
    std::byte* const nodes = out + sphereNodes.size() * sizeof(RealVec4<Real>);
    std::vector<std::uint32_t> recordOf(scene.nodes.size(), kNoRecord);
    runAcrossCores(sphereNodes.size(), kNodesPerPart, [&](std::size_t first, std::size_t end) {
        for (std::size_t record = first; record < end; ++record) {
            recordOf[sphereNodes[record]] = std::uint32_t(record);
        }
    });
    runAcrossCores(scene.nodes.size(), kNodesPerPart, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            const Node& node = scene.nodes[i];
            if (recordOf[i] == kNoRecord) {
                continue;  // a plane
            }
            const GpuNode<Real> packed = packNode<Real>(node, placement, eye, looks.of(node));
            const GpuCandidateSphereNode<Real> record{packed.eyePower, std::uint32_t(i), packed.look};
            std::memcpy(geometry + recordOf[i] * sizeof packed.geometry, &packed.geometry, sizeof packed.geometry);
            std::memcpy(nodes + recordOf[i] * sizeof record, &record, sizeof record);
        }
    });
}

template void packCandidateSpheresInto<float>(const Scene&, const Placement&, std::span<const std::uint32_t>,
                                              const LookIndex&, std::byte*);
template void packCandidateSpheresInto<double>(const Scene&, const Placement&, std::span<const std::uint32_t>,
                                               const LookIndex&, std::byte*);

}  // namespace hexray::gpu
