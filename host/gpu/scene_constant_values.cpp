#include "gpu/scene_constant_values.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "gpu/certainty_bound.h"

namespace hexray::inline gpu {
namespace {

using Field = SceneConstant::Field;

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

template <typename Real>
glm::dvec3 xyz(const RealVec4<Real>& v) {
    return glm::dvec3(v.x, v.y, v.z);
}

}  // namespace

template <typename Real>
std::vector<std::byte> sceneConstantValues(const std::vector<SceneConstant>& constants,
                                           const gpu::GpuScene<Real>& scene) {
    std::vector<std::byte> bytes;
    for (const SceneConstant& constant : constants) {
        const std::uint32_t i = constant.index;
        for (std::uint32_t c = 0; c < constant.components; ++c) {
            switch (constant.field) {
                case Field::Geometry:
                    append<Real>(bytes, scene.nodes[i].geometry[c]);
                    break;
                case Field::EyePower:
                    append<Real>(bytes, scene.nodes[i].eyePower);
                    break;
                case Field::Color1:
                    append<float>(bytes, scene.looks[scene.nodes[i].look].color1[c]);
                    break;
                case Field::Color2:
                    append<float>(bytes, scene.looks[scene.nodes[i].look].color2[c]);
                    break;
                case Field::Checker:
                    append<Real>(bytes, scene.looks[scene.nodes[i].look].checker[c]);
                    break;
                case Field::LightPosition:
                    append<Real>(bytes, scene.lights[i].position[c]);
                    break;
                case Field::LightPower:
                    append<Real>(bytes, scene.lights[i].power[c]);
                    break;
                case Field::LightNodePower:
                    append<Real>(bytes, Real(lightNodePower(scene.lights[i], scene.nodes[constant.node])));
                    break;
                case Field::Ambient:
                    append<float>(bytes, scene.frame.ambient[c]);
                    break;
                case Field::Background:
                    append<float>(bytes, scene.frame.background[c]);
                    break;
                case Field::CertaintyBound:
                    append<Real>(bytes, Real(certaintyBound(xyz<Real>(scene.frame.sheetTopLeft),
                                                            xyz<Real>(scene.frame.sheetRight),
                                                            xyz<Real>(scene.frame.sheetDown))));
                    break;
            }
        }
    }
    return bytes;
}

template std::vector<std::byte> sceneConstantValues<float>(const std::vector<SceneConstant>&,
                                                           const gpu::GpuScene<float>&);
template std::vector<std::byte> sceneConstantValues<double>(const std::vector<SceneConstant>&,
                                                            const gpu::GpuScene<double>&);

}  // namespace hexray::gpu
