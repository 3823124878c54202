#include "scene/scene_writer.h"

#include <string>
#include <variant>

#include <nlohmann/json.hpp>

namespace hexray::inline scene {
namespace {

using OrderedJson = nlohmann::ordered_json;  // keys in the order written, as a person would

OrderedJson triple(const glm::dvec3& v) {
    return OrderedJson::array({v.x, v.y, v.z});
}

OrderedJson imageJson(const ImageSettings& image) {
    OrderedJson json = {{"width", image.width}, {"height", image.height}};
    json["sampling"] = image.sampling == Sampling::Center ? "center" : "corner";
    json["encoding"] = image.encoding == Encoding::Srgb ? "srgb" : "linear";
    json["spp"] = image.samplesPerPixel;
    return json;
}

OrderedJson cameraJson(const CameraSettings& camera) {
    OrderedJson json = {{"position", triple(camera.position)},
                        {"yaw", camera.yawDegrees},
                        {"pitch", camera.pitchDegrees},
                        {"roll", camera.rollDegrees},
                        {"fov", camera.fovDegrees}};
    if (camera.aspect) {
        json["aspect"] = *camera.aspect;
    }
    return json;
}

OrderedJson shaderJson(const Shader& shader) {
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        return {{"type", "constant"}, {"color", triple(constant->color)}};
    }
    if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        return {{"type", "lambert"}, {"color", triple(lambert->color)}};
    }
    const auto& checker = std::get<CheckerShader>(shader);
    return {{"type", "checker"},
            {"color1", triple(checker.color1)},
            {"color2", triple(checker.color2)},
            {"size", checker.size}};
}

OrderedJson geometryJson(const Geometry& geometry) {
    if (const auto* plane = std::get_if<Plane>(&geometry)) {
        return {{"type", "plane"}, {"y", plane->height}};
    }
    const auto& sphere = std::get<Sphere>(geometry);
    return {{"type", "sphere"}, {"center", triple(sphere.center)}, {"radius", sphere.radius}};
}

// `items` as a JSON array with one element per line.
template <class Items, class ToJson>
std::string arrayLines(const Items& items, ToJson&& toJson) {
    std::string text = "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
        text += (i ? ",\n    " : "\n    ") + toJson(items[i]).dump();
    }
    return text + (items.empty() ? "]" : "\n  ]");
}

}  // namespace

std::string sceneToJson(const Scene& scene) {
    std::string shaders = "{";
    for (std::size_t i = 0; i < scene.shaders.size(); ++i) {
        shaders += (i ? ",\n    " : "\n    ") + OrderedJson(scene.shaderNames.at(i)).dump() + ": " +
                   shaderJson(scene.shaders[i]).dump();
    }
    shaders += scene.shaders.empty() ? "}" : "\n  }";
    const auto light = [](const PointLight& l) {
        return OrderedJson{{"position", triple(l.position)}, {"color", triple(l.color)}, {"intensity", l.intensity}};
    };
    const auto node = [&](const Node& n) {
        return OrderedJson{{"geometry", geometryJson(n.geometry)}, {"shader", scene.shaderNames.at(n.shaderIndex)}};
    };
    return "{\n  \"image\": " + imageJson(scene.image).dump() + ",\n  \"camera\": " + cameraJson(scene.camera).dump() +
           ",\n  \"background\": " + triple(scene.background).dump() +
           ",\n  \"ambient\": " + triple(scene.ambient).dump() + ",\n  \"lights\": " + arrayLines(scene.lights, light) +
           ",\n  \"shaders\": " + shaders + ",\n  \"nodes\": " + arrayLines(scene.nodes, node) + "\n}\n";
}

}  // namespace hexray::scene
