#include "kernels/scene_constants.h"

#include "shader_interface.h"

namespace hexray::inline kernels {
namespace {

using Field = SceneConstant::Field;

std::string nodeName(std::uint32_t node, const char* what) {
    return "NODE" + std::to_string(node) + "_" + what;
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
    if (code.certified) {
        constants.push_back({Field::CertaintyBound, 0, 0, 1, true, "CERTAINTY_BOUND"});
    }
    return constants;
}

}  // namespace hexray::kernels
