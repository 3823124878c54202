#pragma once
// A scene as EmbreePacketRenderer traces and shades it: every quantity rounded once to float,
// positions camera-relative (the eye at the origin, as hexray's f32 shader has them), laid out for
// loops over a packet's lanes.

#include <cstdint>
#include <memory>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace hexray::inline embree {

// How a node's shader colours it.
enum class Look : std::uint8_t { Constant, Lambert, PlaneChecker, SphereChecker };

struct NodeLook {
    Look look = Look::Constant;
    glm::vec3 color1{0.0f};  // Constant's and Lambert's colour; a checker's even cells
    glm::vec3 color2{0.0f};  // a checker's odd cells
    float size = 1.0f;       // a checker's cell size
    float inverseSize = 1.0f;
    // Plane checker: the eye's position inside its cell, in cells (x, z), and the parity of the
    // eye's whole cells, from the host in double, so that the cells stay exact far from the origin.
    glm::vec2 eyeCell{0.0f};
    float eyeParity = 0.0f;
};

struct EmbreeFloatScene {
    EmbreeFloatScene(RTCDevice device, const Scene& scene);

    std::unique_ptr<RTCSceneTy, decltype(&rtcReleaseScene)> spheres;  // Embree's, every sphere
    std::vector<glm::vec4> sphereData;                                // by primID: centre, radius
    std::vector<float> shadowOffsets;        // by primID: how far shadow rays start off the sphere
    std::vector<std::uint32_t> sphereNodes;  // by primID: index into Scene::nodes
    std::vector<float> planeHeights;         // camera-relative
    std::vector<std::uint32_t> planeNodes;
    std::vector<NodeLook> looks;  // by node
    std::vector<glm::vec3> lightPositions;
    std::vector<glm::vec3> lightPowers;  // colour times intensity
    glm::vec3 ambient{0.0f};
    glm::vec3 background{0.0f};
    // The camera: the pixel sheet (camera/camera.h) and each sample's offset inside its pixel.
    glm::vec3 topLeft{0.0f};
    glm::vec3 right{0.0f};
    glm::vec3 down{0.0f};
    std::vector<glm::vec2> sampleOffsets;
    float width = 1.0f;
    float height = 1.0f;

private:
    void addSpheres(RTCDevice device, const Scene& scene, const std::vector<std::uint32_t>& nodes);
};

}  // namespace hexray::embree
