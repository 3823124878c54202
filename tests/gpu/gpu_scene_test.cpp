// Packing the scene for the shader: camera-relative, rescaled positions and the checker's cell
// phase.

#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/gpu_scene.h"

namespace hexray {
namespace {

Scene checkerPlaneAndBall(const glm::dvec3& eye) {
    Scene scene;
    scene.camera.position = eye;
    scene.shaderNames = {"floor", "ball"};
    scene.shaders = {CheckerShader{Color(1), Color(0), 20.0}, CheckerShader{Color(1), Color(0), 9.0}};
    scene.nodes = {Node{Plane{15.0}, 0}, Node{Sphere{{-10, 60, 0}, 30}, 1}};
    scene.lights = {PointLight{{30, 100, -70}, Color(0.5, 1, 1), 10000}};
    return scene;
}

gpu::GpuScene<float> packRelative(const Scene& scene) {
    return gpu::packScene<float>(scene, placementFor(scene, Formulation::Robust));
}

const gpu::GpuLook<float>& lookOf(const gpu::GpuScene<float>& packed, std::size_t node) {
    return packed.looks.at(packed.nodes.at(node).look);
}

TEST(PackScene, PositionsAreRelativeToTheEyeAndScaledByAPowerOfTwo) {
    const Scene scene = checkerPlaneAndBall({1, 60, -120});
    // Lengths from the checker's 20 to the sphere's far side |(-11, 0, 120)| + 30 = 150.5: their
    // geometric middle, 54.9, rounds to 2^6.
    ASSERT_EQ(placementScale(scene), 64.0);
    const gpu::GpuScene<float> packed = packRelative(scene);
    EXPECT_EQ(packed.frame.origin, glm::vec4(0));
    EXPECT_EQ(packed.nodes[0].geometryKind, gpu::GEOMETRY_PLANE);
    EXPECT_EQ(packed.nodes[0].geometry.x, (15.0f - 60.0f) / 64);
    EXPECT_EQ(packed.nodes[1].geometryKind, gpu::GEOMETRY_SPHERE);
    EXPECT_EQ(packed.nodes[1].geometry, glm::vec4(-11, 0, 120, 30) / 64.0f);
    EXPECT_EQ(packed.lights[0].position, glm::vec4(29, 40, 50, 0) / 64.0f);
    // 1/r^2 falloff in units 64 times larger: the power is 64^2 times smaller.
    EXPECT_EQ(glm::vec3(packed.lights[0].power), glm::vec3(5000, 10000, 10000) / (64.0f * 64.0f));
    EXPECT_EQ(packed.frame.nodeCount, 2u);
    EXPECT_EQ(packed.frame.lightCount, 1u);
}

TEST(PackScene, WorldPlacementUploadsTheSceneAsWritten) {
    const gpu::GpuScene<float> packed =
        gpu::packScene<float>(checkerPlaneAndBall({1, 60, -120}), placementFor(Scene{}, Formulation::Textbook));
    EXPECT_EQ(packed.frame.origin, glm::vec4(1, 60, -120, 0));
    EXPECT_EQ(packed.nodes[0].geometry.x, 15.0f);
    EXPECT_EQ(packed.nodes[1].geometry, glm::vec4(-10, 60, 0, 30));
    EXPECT_EQ(lookOf(packed, 0).checker, glm::vec4(20, 0, 0, 0));
}

TEST(PackScene, DoubleLayoutKeepsWhatFloatWouldRound) {
    Scene scene = checkerPlaneAndBall({0, 0, 0});
    scene.nodes[1].geometry = Sphere{{0.1, 0, 100}, 1};
    const double scale = placementScale(scene);
    EXPECT_EQ(gpu::packScene<double>(scene, placementFor(scene, Formulation::Robust)).nodes[1].geometry.x, 0.1 / scale);
}

TEST(PackScene, DoubleLayoutKeepsALightPowerBeyondFloatsRange) {
    // Lengths from 1 to 1e50 place at scale 2^83: the power 0.5e100 / 2^166 = 5.3e49 is inf in float.
    Scene scene;
    scene.shaderNames = {"grey"};
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{Sphere{{0, 0, 5}, 1}, 0}};
    scene.lights = {PointLight{{0, 1e50, 0}, Color(0.5), 1e100}};
    const double scale = placementScale(scene);
    ASSERT_EQ(scale, std::exp2(83));
    const gpu::GpuScene<double> packed = gpu::packScene<double>(scene, placementFor(scene, Formulation::Robust));
    EXPECT_DOUBLE_EQ(packed.lights[0].power.x, 0.5 * 1e100 / (scale * scale));
}

TEST(PackScene, AFarAwaySceneUploadsTheSameNumbersAsOneAtTheOrigin) {
    const glm::dvec3 far(3e7, -2e7, 1e7);
    Scene moved = checkerPlaneAndBall(glm::dvec3(0, 60, -120) + far);
    moved.nodes[0].geometry = Plane{15.0 + far.y};
    moved.nodes[1].geometry = Sphere{glm::dvec3(-10, 60, 0) + far, 30};
    moved.lights[0].position += far;
    const gpu::GpuScene<float> atOrigin = packRelative(checkerPlaneAndBall({0, 60, -120}));
    const gpu::GpuScene<float> packed = packRelative(moved);
    EXPECT_EQ(packed.nodes[0].geometry, atOrigin.nodes[0].geometry);
    EXPECT_EQ(packed.nodes[1].geometry, atOrigin.nodes[1].geometry);
    EXPECT_EQ(packed.lights[0].position, atOrigin.lights[0].position);
}

TEST(PackScene, ALightASphereHidesFromEveryVisiblePointIsMarked) {
    EXPECT_EQ(packRelative(checkerPlaneAndBall({0, 60, -120})).lights[0].position.w, 0.0f);
    // From inside the ball every point seen lies in it, and the light is outside it.
    EXPECT_EQ(packRelative(checkerPlaneAndBall({-10, 60, 0})).lights[0].position.w, 1.0f);
}

TEST(PackScene, ALightNoPlaneMayShadowIsMarkedAndTheFrameCountsThePlanes) {
    // The floor lies at 15: the eye and the light above it, then the eye below it.
    EXPECT_EQ(packRelative(checkerPlaneAndBall({0, 60, -120})).lights[0].power.w, 1.0f);
    EXPECT_EQ(packRelative(checkerPlaneAndBall({0, 10, -120})).lights[0].power.w, 0.0f);
    Scene onThePlane = checkerPlaneAndBall({0, 60, -120});
    onThePlane.lights[0].position.y = 15.0;
    EXPECT_EQ(packRelative(onThePlane).lights[0].power.w, 0.0f);
    EXPECT_EQ(packRelative(onThePlane).frame.planeCount, 1u);
    EXPECT_EQ(packRelative(onThePlane).frame.nodeCount, 2u);
}

TEST(PackScene, PlaneCheckerCarriesTheEyesCellFractionAndParity) {
    // Eye x / 20 = -1.25: cell -2, fraction 0.75; z / 20 = 2.35: cell 2, fraction 0.35; parity 0.
    const Scene scene = checkerPlaneAndBall({-25, 60, 47});
    gpu::GpuScene<float> packed = packRelative(scene);
    EXPECT_FLOAT_EQ(lookOf(packed, 0).checker.x, float(20.0 / placementScale(scene)));
    EXPECT_NEAR(lookOf(packed, 0).checker.y, 0.75f, 1e-7f);
    EXPECT_NEAR(lookOf(packed, 0).checker.z, 0.35f, 1e-6f);
    EXPECT_EQ(lookOf(packed, 0).checker.w, 0.0f);
    // x / 20 = 1.5: cell 1 (odd), z cell 0: parity 1.
    packed = packRelative(checkerPlaneAndBall({30, 60, 0}));
    EXPECT_EQ(lookOf(packed, 0).checker.w, 1.0f);
    // Cells -3 and 1e6 + 1 (both odd): parity 0, at coordinates float32 could not hold exactly.
    packed = packRelative(checkerPlaneAndBall({-50, 60, 20e6 + 30}));
    EXPECT_EQ(lookOf(packed, 0).checker.w, 0.0f);
    EXPECT_NEAR(lookOf(packed, 0).checker.z, 0.5f, 1e-6f);
}

TEST(PackScene, SphereCheckerUsesAnglesThatDoNotMoveWithTheEye) {
    const gpu::GpuScene<float> packed = packRelative(checkerPlaneAndBall({-25, 60, 47}));
    EXPECT_EQ(lookOf(packed, 1).checker, glm::vec4(9, 0, 0, 0));
}

TEST(PackScene, SphereCheckerSizesFromAFullTurnOnGiveTheCellsOf360Degrees) {
    // 2e43 degrees would be inf in float (lon / inf = -0 for lon < 0: cell 0, not -1).
    Scene scene = checkerPlaneAndBall({-25, 60, 47});
    scene.shaders[1] = CheckerShader{Color(1), Color(0), 2e43};
    EXPECT_EQ(lookOf(packRelative(scene), 1).checker, glm::vec4(360, 0, 0, 0));
    scene.shaders[1] = CheckerShader{Color(1), Color(0), 359.0};
    EXPECT_EQ(lookOf(packRelative(scene), 1).checker, glm::vec4(359, 0, 0, 0));
}

TEST(PackScene, ALargeScenesNodesAndSphereRecordsEachLandInTheirOwnPlace) {
    // Enough nodes to be packed on several threads, in parts.
    Scene scene = checkerPlaneAndBall({0, 60, -120});
    const std::size_t spheres = 300000;
    for (std::size_t i = 0; i < spheres; ++i) {
        scene.nodes.push_back(Node{Sphere{{double(i), 1, 5}, 0.5}, std::uint32_t(i % 2)});
    }
    const Placement placement = placementFor(Scene{}, Formulation::Textbook);  // positions as written
    std::vector<gpu::GpuNode<float>> nodes(scene.nodes.size());
    gpu::packNodesInto<float>(scene, placement, gpu::LookIndex(scene), reinterpret_cast<std::byte*>(nodes.data()));
    std::vector<std::uint32_t> sphereNodes(spheres);
    for (std::size_t record = 0; record < spheres; ++record) {
        sphereNodes[record] = std::uint32_t(scene.nodes.size() - 1 - record);  // last node first
    }
    // Every record's geometry, then every record's node part.
    std::vector<std::byte> bytes(spheres * gpu::kCandidateSphereBytes<float>);
    gpu::packCandidateSpheresInto<float>(scene, placement, sphereNodes, gpu::LookIndex(scene), bytes.data());
    std::vector<gpu::RealVec4<float>> geometry(spheres);
    std::vector<gpu::GpuCandidateSphereNode<float>> records(spheres);
    std::memcpy(geometry.data(), bytes.data(), spheres * sizeof geometry[0]);
    std::memcpy(records.data(), bytes.data() + spheres * sizeof geometry[0], spheres * sizeof records[0]);
    for (std::size_t i = 2; i < scene.nodes.size(); ++i) {
        ASSERT_EQ(nodes[i].geometry.x, float(i - 2)) << i;
        const std::size_t record = scene.nodes.size() - 1 - i;
        ASSERT_EQ(records[record].node, i) << record;
        ASSERT_EQ(geometry[record].x, float(i - 2)) << record;
        ASSERT_EQ(geometry[record].w, 0.5f) << record;
        ASSERT_EQ(records[record].look, nodes[i].look) << record;
        ASSERT_EQ(records[record].eyePower, nodes[i].eyePower) << record;
    }
    EXPECT_NE(records[0].look, records[1].look);  // two shaders, two looks
}

TEST(PackScene, NodesOfOneShaderAndKindShareALookAndAShaderOnPlanesAndSpheresHasTwo) {
    Scene scene = checkerPlaneAndBall({-25, 60, 47});
    scene.shaderNames.push_back("red");
    scene.shaders.push_back(LambertShader{Color(1, 0, 0)});
    // Nodes: floor (checker 0), ball (checker 1), then red, checker 0 and checker 1 spheres, a red plane.
    scene.nodes.push_back(Node{Sphere{{0, 0, 0}, 1}, 2});
    scene.nodes.push_back(Node{Sphere{{5, 0, 0}, 1}, 0});
    scene.nodes.push_back(Node{Sphere{{9, 0, 0}, 1}, 1});
    scene.nodes.push_back(Node{Plane{-5.0}, 2});
    const gpu::GpuScene<float> packed = packRelative(scene);
    std::vector<std::uint32_t> looks;
    for (const gpu::GpuNode<float>& node : packed.nodes) {
        looks.push_back(node.look);
    }
    EXPECT_EQ(looks, (std::vector<std::uint32_t>{0, 1, 2, 3, 1, 4}));
    ASSERT_EQ(packed.looks.size(), 5u);
    EXPECT_EQ(packed.looks[2].shaderKind, gpu::SHADER_LAMBERT);
    EXPECT_EQ(packed.looks[2].color1, glm::vec3(1, 0, 0));
    EXPECT_EQ(packed.looks[4].color1, glm::vec3(1, 0, 0));
    // Checker 0 on the floor is a plane's (the eye's cell phase), on the sphere an angle's.
    EXPECT_EQ(packed.looks[0].shaderKind, gpu::SHADER_CHECKER);
    EXPECT_NEAR(packed.looks[0].checker.y, 0.75f, 1e-7f);
    EXPECT_EQ(packed.looks[3].checker, glm::vec4(20, 0, 0, 0));
}

}  // namespace
}  // namespace hexray
