#include "scene/random_spheres.h"

#include <cmath>
#include <random>

namespace hexray::inline scene {

namespace {

// Uniform in [0, 1): the top 53 bits of the engine's output, exactly representable.
double uniform01(std::mt19937_64& engine) {
    return double(engine() >> 11) * 0x1.0p-53;
}

double uniform(std::mt19937_64& engine, double low, double high) {
    return low + (high - low) * uniform01(engine);
}

}  // namespace

Scene makeRandomSpheresScene(std::uint32_t count, std::uint64_t seed) {
    std::mt19937_64 engine(seed);
    Scene scene;
    scene.image.width = 320;
    scene.image.height = 180;
    scene.background = {0.05, 0.07, 0.12};
    scene.ambient = Color(0.1);

    // About one sphere per 16 square units of floor.
    const double side = 4.0 * std::sqrt(double(count)) + 10.0;
    scene.camera.position = {0.0, 0.45 * side, -0.55 * side};
    scene.camera.pitchDegrees = -35.0;
    scene.camera.fovDegrees = 90.0;

    scene.lights.push_back(PointLight{{-0.3 * side, 0.8 * side, 0.1 * side}, Color(1.0), 0.6 * side * side});
    scene.lights.push_back(PointLight{{0.4 * side, 0.5 * side, 0.7 * side}, {0.9, 0.8, 0.6}, 0.3 * side * side});

    scene.shaderNames = {"floor", "red", "green", "blue", "checkered", "glow"};
    scene.shaders.push_back(CheckerShader{{0.8, 0.8, 0.8}, {0.2, 0.2, 0.25}, 4.0});
    scene.shaders.push_back(LambertShader{{0.8, 0.2, 0.2}});
    scene.shaders.push_back(LambertShader{{0.2, 0.8, 0.3}});
    scene.shaders.push_back(LambertShader{{0.2, 0.3, 0.9}});
    scene.shaders.push_back(CheckerShader{{0.9, 0.9, 0.2}, {0.1, 0.1, 0.1}, 30.0});
    scene.shaders.push_back(ConstantShader{{1.0, 0.9, 0.7}});

    scene.nodes.push_back(Node{Plane{0.0}, 0});
    for (std::uint32_t i = 0; i < count; ++i) {
        Sphere sphere;
        sphere.radius = uniform(engine, 0.5, 2.5);
        sphere.center.x = uniform(engine, -0.5 * side, 0.5 * side);
        sphere.center.z = uniform(engine, 0.0, side);
        // Most rest on the floor; some float a little above it.
        sphere.center.y = sphere.radius + (uniform01(engine) < 0.75 ? 0.0 : uniform(engine, 0.0, 4.0));
        const auto shader = 1 + static_cast<std::uint32_t>(uniform01(engine) * 5.0);  // 1..5
        scene.nodes.push_back(Node{sphere, shader});
    }
    return scene;
}

}  // namespace hexray::scene
