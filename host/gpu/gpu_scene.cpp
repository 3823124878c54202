#include "gpu/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

template <typename Real>
GpuNode<Real> packNode(const Node& node, const Shader& shader, const Placement& placement, const glm::dvec3& eye) {
    GpuNode<Real> packed{};
    const auto* plane = std::get_if<Plane>(&node.geometry);
    if (plane) {
        packed.kinds.x = GEOMETRY_PLANE;
        packed.geometry = toReal4<Real>(glm::dvec3(placement.position(glm::dvec3(0.0, plane->height, 0.0)).y, 0, 0));
    } else {
        const auto& sphere = std::get<Sphere>(node.geometry);
        packed.kinds.x = GEOMETRY_SPHERE;
        packed.geometry = toReal4<Real>(placement.position(sphere.center), placement.length(sphere.radius));
        const glm::dvec3 fromCenter = placement.position(eye) - placement.position(sphere.center);
        packed.surface = toReal4<Real>(glm::dvec3(eyePower(fromCenter, placement.length(sphere.radius)), 0, 0));
    }
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        packed.kinds.y = SHADER_CONSTANT;
        packed.color1 = toColor(constant->color);
    } else if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        packed.kinds.y = SHADER_LAMBERT;
        packed.color1 = toColor(lambert->color);
    } else {
        const auto& checker = std::get<CheckerShader>(shader);
        packed.kinds.y = SHADER_CHECKER;
        packed.color1 = toColor(checker.color1);
        packed.color2 = toColor(checker.color2);
        // Sphere checkers use angles, which neither move with the eye nor scale.
        packed.checker = plane ? planeCheckerPhase<Real>(placement.origin, checker.size, placement.length(checker.size))
                               : toReal4<Real>(glm::dvec3(checker.size, 0, 0));
    }
    return packed;
}

}  // namespace

template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement) {
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
    frame.planeCount = std::uint32_t(scene.nodes.size() - countSpheres(scene));

    for (const Node& node : scene.nodes) {
        packed.nodes.push_back(packNode<Real>(node, scene.shaders[node.shaderIndex], placement, sheet.origin));
    }
    // Irradiance falls off as 1/r^2: lengths divided by s need intensities divided by s^2.
    const double powerScale = 1.0 / (placement.scale * placement.scale);
    for (const PointLight& light : scene.lights) {
        packed.lights.push_back({toReal4<Real>(placement.position(light.position)),
                                 toColor(light.color * (light.intensity * powerScale))});
    }
    return packed;
}

template GpuScene<float> packScene<float>(const Scene&, const Placement&);
template GpuScene<double> packScene<double>(const Scene&, const Placement&);

namespace {

// Bounds for the shader's BVH. Its slab test allows for its own rounding (shaders/bvh.glsl);
// the pad covers the other side: a ray that rounding lets hit a sphere while it passes just
// outside. That error is a few units of roundoff of the distances involved, all below the
// scene's extent, so a pad of 64 units of roundoff of that extent is ample.
template <typename Real>
class BvhBounds {
public:
    BvhBounds(const Bvh& bvh, const GpuScene<Real>& packed) : bvh_(bvh), packed_(packed) {
        double extent = std::max({std::abs(packed.frame.origin.x), std::abs(packed.frame.origin.y),
                                  std::abs(packed.frame.origin.z)});
        for (const auto& node : packed.nodes) {
            if (node.kinds.x == GEOMETRY_SPHERE) {
                extent = std::max(extent, maxAbs(node.geometry) + double(node.geometry.w));
            }
        }
        for (const auto& light : packed.lights) {
            extent = std::max(extent, maxAbs(light.position));
        }
        pad_ = 64.0 * double(std::numeric_limits<Real>::epsilon()) * extent;
    }

    // Fills `nodes` (already sized) below `index`; returns the subtree's depth.
    std::uint32_t fill(std::uint32_t index, std::vector<GpuBvhNode<Real>>& nodes) const {
        const BvhNode& node = bvh_.nodes[index];
        GpuBvhNode<Real>& out = nodes[index];
        out.firstOrSecondChild = node.firstOrSecondChild;
        out.count = node.count;
        if (node.isLeaf()) {
            glm::dvec3 low(std::numeric_limits<double>::infinity());
            glm::dvec3 high(-std::numeric_limits<double>::infinity());
            for (std::uint32_t i = 0; i < node.count; ++i) {
                const RealVec4<Real>& sphere = packed_.nodes[bvh_.sphereNodes[node.firstOrSecondChild + i]].geometry;
                const glm::dvec3 centre(sphere.x, sphere.y, sphere.z);
                low = glm::min(low, centre - (double(sphere.w) + pad_));
                high = glm::max(high, centre + (double(sphere.w) + pad_));
            }
            // The pad is far above Real's rounding of the bounds.
            out.boundsMin = glm::vec<3, Real>(low);
            out.boundsMax = glm::vec<3, Real>(high);
            return 1;
        }
        const std::uint32_t first = index + 1;
        const std::uint32_t second = node.firstOrSecondChild;
        const std::uint32_t depth = std::max(fill(first, nodes), fill(second, nodes));
        out.boundsMin = glm::min(nodes[first].boundsMin, nodes[second].boundsMin);
        out.boundsMax = glm::max(nodes[first].boundsMax, nodes[second].boundsMax);
        return depth + 1;
    }

private:
    static double maxAbs(const RealVec4<Real>& v) {
        return std::max({std::abs(double(v.x)), std::abs(double(v.y)), std::abs(double(v.z))});
    }

    const Bvh& bvh_;
    const GpuScene<Real>& packed_;
    double pad_ = 0.0;
};

}  // namespace

template <typename Real>
GpuBvh<Real> packBvh(const Scene& scene, const Bvh& bvh, const GpuScene<Real>& packed) {
    GpuBvh<Real> result;
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        if (std::holds_alternative<Plane>(scene.nodes[i].geometry)) {
            result.primitives.push_back(i);
        }
    }
    result.primitives.insert(result.primitives.end(), bvh.sphereNodes.begin(), bvh.sphereNodes.end());
    if (!bvh.nodes.empty()) {
        result.nodes.resize(bvh.nodes.size());
        result.depth = BvhBounds<Real>(bvh, packed).fill(0, result.nodes);
    }
    return result;
}

template GpuBvh<float> packBvh<float>(const Scene&, const Bvh&, const GpuScene<float>&);
template GpuBvh<double> packBvh<double>(const Scene&, const Bvh&, const GpuScene<double>&);

}  // namespace hexray::gpu
