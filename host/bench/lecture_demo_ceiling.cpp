#include "bench/lecture_demo_ceiling.h"

#include <stdexcept>
#include <variant>

namespace {
// SPIR-V compiled from host/bench/lecture_demo_ceiling.comp at build time.
#include "kLectureDemoCeilingSpv.h"
}  // namespace

namespace hexray::inline bench {

namespace {

bool isShader(const Scene& scene, const Node& node, const Shader& expected) {
    const Shader& shader = scene.shaders.at(node.shaderIndex);
    if (shader.index() != expected.index()) {
        return false;
    }
    if (const auto* checker = std::get_if<CheckerShader>(&shader)) {
        const auto& wanted = std::get<CheckerShader>(expected);
        return checker->color1 == wanted.color1 && checker->color2 == wanted.color2 && checker->size == wanted.size;
    }
    const auto* lambert = std::get_if<LambertShader>(&shader);
    return lambert && lambert->color == std::get<LambertShader>(expected).color;
}

}  // namespace

bool isLectureDemoScene(const Scene& scene) {
    if (scene.image.samplesPerPixel != 1 || scene.camera.position != glm::dvec3(0, 60, -120) ||
        scene.background != Color(0) || scene.ambient != Color(0.15) || scene.lights.size() != 1 ||
        scene.nodes.size() != 2) {
        return false;
    }
    const PointLight& light = scene.lights[0];
    if (light.position != glm::dvec3(30, 100, -70) || light.color != Color(1) || light.intensity != 10000) {
        return false;
    }
    const auto* plane = std::get_if<Plane>(&scene.nodes[0].geometry);
    const auto* sphere = std::get_if<Sphere>(&scene.nodes[1].geometry);
    return plane && plane->height == 0 && sphere && sphere->center == glm::dvec3(-10, 60, 0) && sphere->radius == 10 &&
           isShader(scene, scene.nodes[0], CheckerShader{Color(0, 0, 0.8), Color(0.2, 0.3, 0.6), 20}) &&
           isShader(scene, scene.nodes[1], LambertShader{Color(0.8, 0, 0)});
}

RenderPlan lectureDemoCeilingPlan(const GpuRenderer& renderer, const Scene& scene) {
    if (!isLectureDemoScene(scene)) {
        throw std::invalid_argument("the lecture demo's hand-written kernel renders only that scene");
    }
    RenderPlan plan = renderer.plan(scene, {Precision::F32, Acceleration::Auto, Culling::Off});
    // Its blocks are the uniform layout's, which the demo scene (2 nodes) is planned with.
    plan.kernel = Kernel{"lecture demo, hand-written", nullptr, kLectureDemoCeilingSpv};
    return plan;
}

}  // namespace hexray::bench
