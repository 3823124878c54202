#pragma once
// The scene model: what a scene file describes, in world coordinates and double precision.
// Both renderers read this; neither adds anything to it.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

namespace hexray::inline scene {

using Color = glm::dvec3;  // linear RGB, not clamped

enum class Sampling { Center, Corner };  // where in a pixel its ray aims
enum class Encoding { Srgb, Linear };    // transfer function of the 8-bit output

struct ImageSettings {
    std::uint32_t width = 800;
    std::uint32_t height = 600;
    Sampling sampling = Sampling::Center;
    Encoding encoding = Encoding::Srgb;
    std::uint32_t samplesPerPixel = 1;  // anti-aliasing: rays per pixel, averaged
};

// Requests beyond these would take hours rather than render; checked at load time. (The GPU
// path streams the image in bands of rows, so 16384 x 16384 fits in a fixed memory budget.)
inline constexpr std::uint32_t kMaxImageDimension = 16384;
inline constexpr std::uint32_t kMaxSamplesPerPixel = 1024;
inline constexpr std::uint64_t kMaxImageSamples = std::uint64_t{1} << 32;  // width x height x spp

// The supported range, checked at load time: every length (a coordinate, plane height, radius or
// checker size) is 0 or has a magnitude in [kMinSceneLength, kMaxSceneLength] (radii and checker
// sizes are never 0); a light's intensity (an irradiance at distance 1, so a length squared) is 0 or
// in [kMinIntensity, kMaxIntensity]; colour components are at most kMaxColorComponent.
// Within it no difference, square or product of two lengths over- or underflows a double, and the
// scene's dynamic range fits the GPU's float64 (and float32 when it is below 2^100, see
// host/precision/precision.h).
inline constexpr double kMinSceneLength = 1e-50;
inline constexpr double kMaxSceneLength = 1e50;
inline constexpr double kMinIntensity = 1e-100;
inline constexpr double kMaxIntensity = 1e100;
inline constexpr double kMaxColorComponent = 1e10;

// Whether `value` is a length in the supported range: 0 (where allowed) or of magnitude within
// [kMinSceneLength, kMaxSceneLength].
inline bool isSupportedLength(double value, bool mayBeZero = true) {
    const double magnitude = value < 0 ? -value : value;
    return (mayBeZero && value == 0.0) || (magnitude >= kMinSceneLength && magnitude <= kMaxSceneLength);
}

struct CameraSettings {
    glm::dvec3 position{0.0};
    double yawDegrees = 0.0;       // + turns the view toward -X
    double pitchDegrees = 0.0;     // + looks up (+Y)
    double rollDegrees = 0.0;      // + tips the up vector toward +X
    double fovDegrees = 90.0;      // across the frame's diagonal, in (0, 180)
    std::optional<double> aspect;  // width / height of the sheet; default: the image's
};

struct PointLight {
    glm::dvec3 position{0.0};
    Color color{1.0};
    double intensity = 1.0;  // irradiance at distance 1; falls off as 1/r^2
};

struct ConstantShader {
    Color color{1.0};
};
struct LambertShader {
    Color color{1.0};
};
// Lambert whose colour alternates in squares of `size` over the surface's (u, v).
struct CheckerShader {
    Color color1{1.0};
    Color color2{0.0};
    double size = 1.0;
};
using Shader = std::variant<ConstantShader, LambertShader, CheckerShader>;

// The plane y = height, parallel to XZ; texture coordinates (u, v) = (x, z).
struct Plane {
    double height = 0.0;
};
// Texture coordinates (u, v) = (longitude, latitude) of the outward normal, in degrees.
struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 1.0;
};
using Geometry = std::variant<Plane, Sphere>;

struct Node {
    Geometry geometry;
    std::uint32_t shaderIndex = 0;  // into Scene::shaders
};

struct Scene {
    ImageSettings image;
    CameraSettings camera;
    Color background{0.0};
    Color ambient{0.0};
    std::vector<PointLight> lights;
    std::vector<std::string> shaderNames;  // parallel to `shaders`, for messages
    std::vector<Shader> shaders;
    std::vector<Node> nodes;  // order matters: on an exact distance tie the earlier node wins
};

// Width / height the camera uses: the scene's aspect if given, else the image's.
inline double sheetAspect(const Scene& scene) {
    return scene.camera.aspect.value_or(double(scene.image.width) / double(scene.image.height));
}

}  // namespace hexray::scene
