// Reads scene files (JSON) into the scene model. Every rejection is one SceneError whose
// message names the source and the place: the JSON path (nodes[3].geometry.radius) for a
// bad value, line:column for a syntax error.

#include "scene/scene_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/camera_angles.h"
#include "scene/json_reader.h"
#include "scene/light_reader.h"
#include "scene/node_reader.h"
#include "scene/scene_json_parser.h"
#include "scene/text_encoding.h"
#include "util/printable.h"

namespace hexray::inline scene {
namespace {

// Hand-written scenes are kilobytes; a million spheres take some 100 MB, 130 MB with every
// number in full double precision. Loading needs about twice the file's size in memory, so the
// cap stops /dev/zero or a stray huge file from eating it.
constexpr std::size_t kMaxSceneFileBytes = std::size_t{256} << 20;

std::optional<std::string> sampleCountProblem(std::uint64_t width, std::uint64_t height, std::uint64_t spp) {
    const std::uint64_t samples = width * height * spp;  // <= 16384^2 * 1024: no overflow
    if (samples <= kMaxImageSamples)
        return std::nullopt;
    return std::to_string(width) + " x " + std::to_string(height) + " pixels x " + std::to_string(spp) +
           " samples = " + std::to_string(samples) + " exceeds the limit of " + std::to_string(kMaxImageSamples) +
           " samples per image (lower spp or the image size)";
}

// ---------------------------------------------------------------- the scene, part by part

constexpr std::pair<const char*, Sampling> kSamplingNames[] = {{"center", Sampling::Center},
                                                               {"corner", Sampling::Corner}};
constexpr std::pair<const char*, Encoding> kEncodingNames[] = {{"srgb", Encoding::Srgb}, {"linear", Encoding::Linear}};

enum class ShaderType { Constant, Lambert, Checker };
constexpr std::pair<const char*, ShaderType> kShaderTypes[] = {
    {"constant", ShaderType::Constant}, {"lambert", ShaderType::Lambert}, {"checker", ShaderType::Checker}};

ImageSettings readImage(const JsonReader& image) {
    image.rejectUnknownKeys({"width", "height", "sampling", "encoding", "spp"});
    ImageSettings settings;
    settings.width = std::uint32_t(image.at("width").integer(1, kMaxImageDimension));
    settings.height = std::uint32_t(image.at("height").integer(1, kMaxImageDimension));
    settings.sampling = image.choiceOr("sampling", settings.sampling, kSamplingNames);
    settings.encoding = image.choiceOr("encoding", settings.encoding, kEncodingNames);
    if (const auto spp = image.find("spp")) {
        settings.samplesPerPixel = std::uint32_t(spp->integer(1, kMaxSamplesPerPixel));
    }
    if (auto problem = sampleCountProblem(settings.width, settings.height, settings.samplesPerPixel)) {
        image.fail(*problem);
    }
    return settings;
}

// The look-at form's sine of the smallest angle between `up` and the view: closer, and which way
// is up would hang on rounding.
constexpr double kMinUpSine = 1e-9;

// Nonzero `v` at length 1, scaled first so that its square neither overflows nor underflows.
glm::dvec3 unitVector(const glm::dvec3& v) {
    return glm::normalize(v / std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}));
}

// "lookAt" and "up" as the course's angles, converted once here: nothing downstream knows the
// camera was given this way.
CameraAngles readLookAt(const JsonReader& camera, const glm::dvec3& position) {
    for (const char* angle : {"yaw", "pitch", "roll"}) {
        if (const auto found = camera.find(angle)) {
            found->fail("cannot be used with camera.lookAt (a look-at camera's direction comes from lookAt and up)");
        }
    }
    const JsonReader lookAt = camera.at("lookAt");
    const glm::dvec3 target = lookAt.position();
    if (target == position) {
        lookAt.fail("must differ from camera.position (the camera would look nowhere)");
    }
    glm::dvec3 up(0.0, 1.0, 0.0);
    if (const auto given = camera.find("up")) {
        up = given->vec3();
        if (up == glm::dvec3(0.0)) {
            given->fail("must not be zero (it says which way is up in the image)");
        }
    }
    const glm::dvec3 unitUp = unitVector(up);
    if (glm::length(glm::cross(unitVector(target - position), unitUp)) < kMinUpSine) {
        if (const auto given = camera.find("up")) {
            given->fail(
                "must not be parallel to the view direction lookAt - position (which way is up in the image "
                "would be undefined)");
        }
        lookAt.fail(
            "the camera looks straight up or down, along the default up [0, 1, 0]: give camera.up across "
            "the view");
    }
    return lookAtAngles(position, target, unitUp);
}

CameraSettings readCamera(const JsonReader& camera) {
    camera.rejectUnknownKeys({"position", "yaw", "pitch", "roll", "lookAt", "up", "fov", "aspect"});
    CameraSettings settings;  // its defaults are the format's defaults
    settings.position = camera.at("position").position();
    if (camera.find("lookAt")) {
        const CameraAngles angles = readLookAt(camera, settings.position);
        settings.yawDegrees = angles.yawDegrees;
        settings.pitchDegrees = angles.pitchDegrees;
        settings.rollDegrees = angles.rollDegrees;
    } else if (const auto up = camera.find("up")) {
        up->fail("only with camera.lookAt (yaw, pitch and roll say which way is up)");
    } else {
        settings.yawDegrees = camera.numberOr("yaw", settings.yawDegrees);
        settings.pitchDegrees = camera.numberOr("pitch", settings.pitchDegrees);
        settings.rollDegrees = camera.numberOr("roll", settings.rollDegrees);
    }
    settings.fovDegrees = camera.numberOr("fov", settings.fovDegrees, Bounds{.above = 0.0, .below = 180.0});
    if (auto aspect = camera.find("aspect"))
        settings.aspect = aspect->number(kPositive);
    return settings;
}

Shader readShader(const JsonReader& shader) {
    const ShaderType type = shader.at("type").choice(kShaderTypes);
    if (type == ShaderType::Checker) {
        shader.rejectUnknownKeys({"type", "color1", "color2", "size"});
        return CheckerShader{shader.at("color1").colour(), shader.at("color2").colour(),
                             shader.at("size").length(false)};
    }
    shader.rejectUnknownKeys({"type", "color"});
    const Color color = shader.at("color").colour();
    if (type == ShaderType::Constant)
        return ConstantShader{color};
    return LambertShader{color};
}

Scene readScene(const JsonReader& root, NodeReader&& nodes, LightReader&& lights) {
    root.rejectUnknownKeys({"$schema", "image", "camera", "background", "ambient", "lights", "shaders", "nodes"});
    if (const auto schema = root.find("$schema"))
        schema->text();  // for editors (docs/schemas/hexray-scene.schema.json); hexray ignores it
    Scene scene;
    scene.image = readImage(root.at("image"));
    scene.camera = readCamera(root.at("camera"));
    scene.background = root.colourOr("background", scene.background);
    scene.ambient = root.colourOr("ambient", scene.ambient);
    if (auto found = root.find("lights")) {
        found->expectArray();  // its elements went to `lights` while the parser read them
    }
    scene.lights = std::move(lights).take();
    if (auto shaders = root.find("shaders")) {
        for (const auto& [name, shader] : shaders->members()) {
            scene.shaderNames.push_back(name);
            scene.shaders.push_back(readShader(shader));
        }
    }
    root.at("nodes").expectArray();  // its elements went to `nodes` while the parser read them
    scene.nodes = std::move(nodes).resolve(scene.shaderNames);
    return scene;
}

[[noreturn]] void failToRead(const std::filesystem::path& path, int error) {
    throw SceneError(printable(path.string()) + ": cannot read scene file: " + std::strerror(error));
}

[[noreturn]] void failTooLarge(const std::filesystem::path& path) {
    throw SceneError(printable(path.string()) + ": cannot read scene file: larger than " +
                     std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
}

// The rest of `file`, after `text` (which may have room reserved), refused beyond the cap.
std::string readSceneText(std::FILE* file, const std::filesystem::path& path, std::string text = {}) {
    char buffer[1 << 16];
    while (const std::size_t count = std::fread(buffer, 1, sizeof buffer, file)) {
        text.append(buffer, count);
        if (text.size() > kMaxSceneFileBytes)
            failTooLarge(path);
    }
    if (std::ferror(file))
        failToRead(path, errno);
    return text;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& sourceName, const ParseProgress& progress) {
    const std::string source = printable(sourceName);  // the name as every message shows it
    if (const std::optional<std::string> problem = wideEncodingProblem(text)) {
        throw SceneError(source + ": " + *problem);
    }
    // Valid files take the shortcut; a file with a node it declines is parsed again the general way.
    {
        NodeReader nodes(source);
        LightReader lights(source);
        UsualNodeShortcut shortcut(nodes);
        const auto takeLight = [&lights](const Json& element, std::size_t index) { lights.read(element, index); };
        if (const std::optional<Json> document = parseSceneJson(text, source, shortcut, takeLight, progress)) {
            return readScene(JsonReader(*document, source, ""), std::move(nodes), std::move(lights));
        }
    }
    NodeReader nodes(source);
    LightReader lights(source);
    const auto takeNode = [&nodes](const Json& element, std::size_t index) { nodes.read(element, index); };
    const auto takeLight = [&lights](const Json& element, std::size_t index) { lights.read(element, index); };
    const Json document = parseSceneJson(text, source, takeNode, takeLight, progress);
    return readScene(JsonReader(document, source, ""), std::move(nodes), std::move(lights));
}

std::string sceneSourceName(const std::string& path) {
    return path == kStandardInputPath ? "<stdin>" : path;
}

Scene loadSceneFile(const std::filesystem::path& path) {
    return parseScene(readSceneFile(path), sceneSourceName(path.string()));
}

std::string readSceneFile(const std::filesystem::path& path) {
    if (path == kStandardInputPath)
        return readSceneText(stdin, sceneSourceName(path));
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        failToRead(path, EISDIR);  // fopen would accept it

    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file)
        failToRead(path, errno);
    std::string text;
    // A regular file's size is known: a huge one is refused unread, and the text never regrows.
    std::error_code noSize;
    if (const std::uintmax_t size = std::filesystem::file_size(path, noSize); !noSize) {
        if (size > kMaxSceneFileBytes)
            failTooLarge(path);
        text.reserve(size);
    }
    return readSceneText(file.get(), path, std::move(text));
}

void overrideImageSize(Scene& scene, std::int64_t width, std::int64_t height, const std::string& source) {
    // `source` may already name the dimension (e.g. "--width"); otherwise the message must.
    const auto checkDimension = [&](std::int64_t value, const std::string& dimension, const std::string& other) {
        if (value >= 1 && value <= std::int64_t{kMaxImageDimension})
            return;
        const bool sourceNamesIt =
            source.find(dimension) != std::string::npos && source.find(other) == std::string::npos;
        throw SceneError(source + ": " + (sourceNamesIt ? "" : dimension + " ") +
                         rangeProblem(1, kMaxImageDimension, std::to_string(value)));
    };
    checkDimension(width, "width", "height");
    checkDimension(height, "height", "width");
    if (auto problem = sampleCountProblem(std::uint64_t(width), std::uint64_t(height), scene.image.samplesPerPixel)) {
        throw SceneError(source + ": " + *problem);
    }
    scene.image.width = std::uint32_t(width);
    scene.image.height = std::uint32_t(height);
}

void overrideSamplesPerPixel(Scene& scene, std::int64_t samples, const std::string& source) {
    if (samples < 1 || samples > std::int64_t{kMaxSamplesPerPixel}) {
        throw SceneError(source + ": " + rangeProblem(1, kMaxSamplesPerPixel, std::to_string(samples)));
    }
    if (auto problem = sampleCountProblem(scene.image.width, scene.image.height, std::uint64_t(samples))) {
        throw SceneError(source + ": " + *problem);
    }
    scene.image.samplesPerPixel = std::uint32_t(samples);
}

}  // namespace hexray::scene
