// A renderer that renders many scenes keeps only the most recently used pipelines and generated
// kernels (kept_kernels.h), and a scene whose kernel was dropped renders the same image again.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/gpu_renderer.h"
#include "kernels/kept_kernels.h"
#include "scene/scene.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

using KeptKernelsTest = test::ValidatedVulkanTest;

// A small scene whose structure is `structure`'s binary digits (1: a sphere, 0: a plane, from the
// lowest), so each number gives its own generated kernel; `shift` moves the spheres (the same
// kernel, other values: another pipeline).
Scene sceneOfStructure(std::uint32_t structure, double shift = 0.0) {
    Scene scene;
    scene.image.width = 12;
    scene.image.height = 8;
    scene.camera.position = {0, 2, -6};
    scene.ambient = Color(0.1);
    scene.shaderNames = {"matte", "squares"};
    scene.shaders = {LambertShader{Color(0.7, 0.4, 0.2)}, CheckerShader{Color(0.9), Color(0.1), 1.0}};
    scene.lights = {PointLight{{3, 8, -2}, Color(1.0), 60}};
    for (std::uint32_t digit = 0, rest = structure; rest > 0; ++digit, rest >>= 1) {
        if (rest & 1) {
            scene.nodes.push_back(Node{Sphere{{-3.0 + 1.5 * digit + shift, 0.5, 4.0 + digit}, 0.7}, 0});
        } else {
            scene.nodes.push_back(Node{Plane{-1.0 - digit}, 1});
        }
    }
    return scene;
}

TEST_F(KeptKernelsTest, ManyDistinctScenesLeaveAtMostTheBoundsPipelinesAndKernels) {
    GpuRenderer renderer(context());
    const std::uint32_t scenes = std::uint32_t(std::max(kKeptPipelines, kKeptGeneratedKernels)) + 4;
    for (std::uint32_t structure = 1; structure <= scenes; ++structure) {
        renderer.render(sceneOfStructure(structure));
    }
    EXPECT_LE(renderer.keptPipelines(), kKeptPipelines);
    EXPECT_LE(renderer.keptGeneratedKernels(), kKeptGeneratedKernels);
}

TEST_F(KeptKernelsTest, ManyFramesOfOneStructureLeaveAtMostTheBoundsPipelines) {
    GpuRenderer renderer(context());
    for (std::uint32_t frame = 0; frame < kKeptPipelines + 4; ++frame) {
        renderer.render(sceneOfStructure(0b1101, 0.05 * frame));
    }
    EXPECT_LE(renderer.keptPipelines(), kKeptPipelines);
    EXPECT_EQ(renderer.keptGeneratedKernels(), 1u);
}

TEST_F(KeptKernelsTest, ASceneWhoseKernelWasDroppedRendersTheSameImageAgain) {
    GpuRenderer renderer(context());
    const Scene first = sceneOfStructure(0b1011);
    const std::vector<glm::vec3> before = renderer.render(first).image.pixels;
    for (std::uint32_t structure = 0b100000; structure < 0b100000 + kKeptGeneratedKernels + 4; ++structure) {
        renderer.render(sceneOfStructure(structure));
    }
    EXPECT_EQ(renderer.render(first).image.pixels, before);
    GpuRenderer fresh(context());
    EXPECT_EQ(fresh.render(first).image.pixels, before);
}

}  // namespace
}  // namespace hexray
