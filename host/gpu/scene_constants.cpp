#include "gpu/scene_constants.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "shader_interface.h"

namespace hexray {
namespace {

using Field = SceneConstant::Field;

std::string nodeName(std::uint32_t node, const char* what) {
    return "NODE" + std::to_string(node) + "_" + what;
}

template <typename T>
void append(std::vector<std::byte>& bytes, T value) {
    const auto* raw = reinterpret_cast<const std::byte*>(&value);
    bytes.insert(bytes.end(), raw, raw + sizeof value);
}

// The light's power with respect to the sphere, |L - c|^2 - r^2, in double from the packed (rounded)
// values the kernel works with, as (d - r)(d + r): accurate even for a light near the surface.
template <typename Real>
double lightNodePower(const gpu::GpuLight<Real>& light, const gpu::GpuNode<Real>& sphere) {
    const glm::dvec3 l(light.position.x, light.position.y, light.position.z);
    const glm::dvec3 c(sphere.geometry.x, sphere.geometry.y, sphere.geometry.z);
    const double d = glm::length(l - c);
    const double r = double(sphere.geometry.w);
    return (d - r) * (d + r);
}

}  // namespace

std::vector<SceneConstant> sceneConstants(const SceneCode& code) {
    std::vector<SceneConstant> constants;
    for (std::uint32_t i = 0; i < code.nodes.size(); ++i) {
        const NodeCode& node = code.nodes[i];
        const bool sphere = node.geometry == gpu::GEOMETRY_SPHERE;
        constants.push_back({Field::Geometry, i, 0, sphere ? 4u : 1u, true, nodeName(i, "GEOMETRY")});
        if (sphere && node.sphereTest != SphereTest::Textbook) {
            constants.push_back({Field::EyePower, i, 0, 1, true, nodeName(i, "EYE_POWER")});
        }
        constants.push_back({Field::Color1, i, 0, 3, false, nodeName(i, "COLOR1")});
        if (node.shader == gpu::SHADER_CHECKER) {
            constants.push_back({Field::Color2, i, 0, 3, false, nodeName(i, "COLOR2")});
            constants.push_back({Field::Checker, i, 0, 4, true, nodeName(i, "CHECKER")});
        }
    }
    for (std::uint32_t light = 0; light < code.shadowTests.size(); ++light) {
        const std::string prefix = "LIGHT" + std::to_string(light);
        constants.push_back({Field::LightPosition, light, 0, 3, true, prefix + "_POSITION"});
        constants.push_back({Field::LightPower, light, 0, 3, true, prefix + "_POWER"});
        if (code.formulation == Formulation::Robust) {
            for (const ShadowTest& test : code.shadowTests[light]) {
                if (code.nodes[test.node].geometry == gpu::GEOMETRY_SPHERE) {
                    constants.push_back({Field::LightNodePower, light, test.node, 1, true,
                                         prefix + "_NODE" + std::to_string(test.node) + "_POWER"});
                }
            }
        }
    }
    constants.push_back({Field::Ambient, 0, 0, 3, false, "AMBIENT"});
    constants.push_back({Field::Background, 0, 0, 3, false, "BACKGROUND_COLOR"});
    return constants;
}

template <typename Real>
std::vector<std::byte> sceneConstantValues(const std::vector<SceneConstant>& constants, const gpu::GpuScene<Real>& scene) {
    std::vector<std::byte> bytes;
    for (const SceneConstant& constant : constants) {
        const std::uint32_t i = constant.index;
        for (std::uint32_t c = 0; c < constant.components; ++c) {
            switch (constant.field) {
                case Field::Geometry: append<Real>(bytes, scene.nodes[i].geometry[c]); break;
                case Field::EyePower: append<Real>(bytes, scene.nodes[i].surface.x); break;
                case Field::Color1: append<float>(bytes, scene.nodes[i].color1[c]); break;
                case Field::Color2: append<float>(bytes, scene.nodes[i].color2[c]); break;
                case Field::Checker: append<Real>(bytes, scene.nodes[i].checker[c]); break;
                case Field::LightPosition: append<Real>(bytes, scene.lights[i].position[c]); break;
                case Field::LightPower: append<Real>(bytes, scene.lights[i].power[c]); break;
                case Field::LightNodePower:
                    append<Real>(bytes, Real(lightNodePower(scene.lights[i], scene.nodes[constant.node])));
                    break;
                case Field::Ambient: append<float>(bytes, scene.frame.ambient[c]); break;
                case Field::Background: append<float>(bytes, scene.frame.background[c]); break;
            }
        }
    }
    return bytes;
}

template std::vector<std::byte> sceneConstantValues<float>(const std::vector<SceneConstant>&,
                                                           const gpu::GpuScene<float>&);
template std::vector<std::byte> sceneConstantValues<double>(const std::vector<SceneConstant>&,
                                                            const gpu::GpuScene<double>&);

}  // namespace hexray
