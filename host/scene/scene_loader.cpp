// Reads scene files (JSON) into the scene model. Every rejection is one SceneError whose
// message names the source and the place: the JSON path (nodes[3].geometry.radius) for a
// bad value, line:column for a syntax error.

#include "scene/scene_loader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace hexray {
namespace {

using Json = nlohmann::json;

// Scene files are kilobytes; the cap stops /dev/zero or a stray huge file from eating memory.
constexpr std::size_t kMaxSceneFileBytes = std::size_t{64} << 20;

// ---------------------------------------------------------------- formatting for messages

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
    // Shortest round trip; plain digits for everyday magnitudes, so 1e6 reads as 1000000.
    const double magnitude = std::fabs(value);
    const bool everyday = magnitude == 0.0 || (magnitude >= 1e-4 && magnitude < 1e15);
    char buffer[64];
    const auto result = everyday ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                                 : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// Longer user strings are cut in messages, so a huge key or name cannot flood the terminal.
constexpr std::size_t kMaxShown = 40;

// JSON-quoted, so control characters and quotes in user strings stay readable.
std::string quoted(const std::string& text) {
    std::string shown = text.size() > kMaxShown ? text.substr(0, kMaxShown) : text;
    std::string result = Json(shown).dump(-1, ' ', false, Json::error_handler_t::replace);
    if (shown.size() < text.size()) result += "...";
    return result;
}

std::string joined(std::vector<std::string> items, bool sorted = true) {
    if (sorted) std::sort(items.begin(), items.end());
    std::string result;
    for (const std::string& item : items) {
        if (!result.empty()) result += ", ";
        result += item;
    }
    return result;
}

// What a value is, for "expected X (got Y)" messages.
std::string describe(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::boolean: return value.get<bool>() ? "boolean true" : "boolean false";
        case Json::value_t::string: return "string " + quoted(value.get<std::string>());
        case Json::value_t::number_integer: return "number " + std::to_string(value.get<std::int64_t>());
        case Json::value_t::number_unsigned: return "number " + std::to_string(value.get<std::uint64_t>());
        case Json::value_t::number_float: return "number " + formatNumber(value.get<double>());
        case Json::value_t::array:
            return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
        case Json::value_t::object: return "an object";
        default: return "an unsupported value";
    }
}

std::string rangeProblem(std::int64_t min, std::int64_t max, const std::string& got) {
    return "must be between " + std::to_string(min) + " and " + std::to_string(max) + " (got " + got + ")";
}

std::optional<std::string> sampleCountProblem(std::uint64_t width, std::uint64_t height, std::uint64_t spp) {
    const std::uint64_t samples = width * height * spp;  // <= 16384^2 * 1024: no overflow
    if (samples <= kMaxImageSamples) return std::nullopt;
    return std::to_string(width) + " x " + std::to_string(height) + " pixels x " + std::to_string(spp) +
           " samples = " + std::to_string(samples) + " exceeds the limit of " + std::to_string(kMaxImageSamples) +
           " samples per image (lower spp or the image size)";
}

// ---------------------------------------------------------------- JSON paths

bool isIdentifier(std::string_view key) {
    const auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    return !key.empty() && isLetter(key[0]) &&
           std::all_of(key.begin(), key.end(), [&](char c) { return isLetter(c) || isDigit(c); });
}

// "camera" + "fov" -> camera.fov; a key like "my ball" becomes shaders["my ball"].
std::string childPath(const std::string& parent, const std::string& key) {
    if (!isIdentifier(key) || key.size() > kMaxShown) return parent + "[" + quoted(key) + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string elementPath(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string displayPath(const std::string& path) { return path.empty() ? "(root)" : path; }

// ---------------------------------------------------------------- the reader

// Bounds a number must respect; the message spells out the ones given.
struct Bounds {
    std::optional<double> above = std::nullopt;    // exclusive lower bound
    std::optional<double> atLeast = std::nullopt;  // inclusive lower bound
    std::optional<double> below = std::nullopt;    // exclusive upper bound
};
const Bounds kPositive{.above = 0.0};
const Bounds kNonNegative{.atLeast = 0.0};

// One JSON value at a known place in a known source. The typed getters check the value and
// throw SceneError naming source and path, so the scene code below reads as a description.
class JsonReader {
public:
    JsonReader(const Json& value, const std::string& source, std::string path)
        : value_(value), source_(source), path_(std::move(path)) {}

    [[noreturn]] void fail(const std::string& reason) const {
        throw SceneError(source_ + ": " + displayPath(path_) + ": " + reason);
    }

    // ---- objects

    void expectObject() const {
        if (!value_.is_object()) failType("an object");
    }

    // A typo must not be silently ignored: every key must be one the format knows here.
    void rejectUnknownKeys(std::initializer_list<std::string> allowed) const {
        expectObject();
        for (const auto& [key, value] : value_.items()) {
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
                child(key, value).fail("unknown key (allowed: " + joined(allowed) + ")");
            }
        }
    }

    JsonReader at(const std::string& key) const {
        if (auto found = find(key)) return *found;
        JsonReader(Json(), source_, childPath(path_, key)).fail("missing required field");
    }

    std::optional<JsonReader> find(const std::string& key) const {
        expectObject();
        const auto found = value_.find(key);
        if (found == value_.end()) return std::nullopt;
        return child(key, *found);
    }

    // nlohmann keeps objects sorted by key, so the order does not depend on how the file is laid out.
    std::vector<std::pair<std::string, JsonReader>> members() const {
        expectObject();
        std::vector<std::pair<std::string, JsonReader>> result;
        for (const auto& [key, value] : value_.items()) result.emplace_back(key, child(key, value));
        return result;
    }

    // ---- arrays

    std::vector<JsonReader> elements() const {
        if (!value_.is_array()) failType("an array");
        std::vector<JsonReader> result;
        for (std::size_t i = 0; i < value_.size(); ++i) {
            result.emplace_back(value_[i], source_, elementPath(path_, i));
        }
        return result;
    }

    // ---- scalars

    double number(const Bounds& bounds = {}) const {
        if (!value_.is_number()) failType("a number");
        const double value = value_.get<double>();
        if (!std::isfinite(value)) fail("must be a finite number (got " + formatNumber(value) + ")");
        const bool tooLow = (bounds.above && !(value > *bounds.above)) ||
                            (bounds.atLeast && !(value >= *bounds.atLeast));
        const bool tooHigh = bounds.below && !(value < *bounds.below);
        if (tooLow || tooHigh) {
            std::vector<std::string> rules;
            if (bounds.above) rules.push_back("> " + formatNumber(*bounds.above));
            if (bounds.atLeast) rules.push_back(">= " + formatNumber(*bounds.atLeast));
            if (bounds.below) rules.push_back("< " + formatNumber(*bounds.below));
            std::string rule;
            for (const std::string& part : rules) rule += (rule.empty() ? "" : " and ") + part;
            fail("must be " + rule + " (got " + formatNumber(value) + ")");
        }
        return value;
    }

    // JSON has one number type, so 800.0 counts as an integer but 800.5 does not.
    std::int64_t integer(std::int64_t min, std::int64_t max) const {
        if (!value_.is_number()) failType("an integer");
        if (value_.is_number_unsigned()) {
            const std::uint64_t value = value_.get<std::uint64_t>();
            if (value > std::uint64_t(max)) fail(rangeProblem(min, max, std::to_string(value)));
            return checkRange(std::int64_t(value), min, max);
        }
        if (value_.is_number_integer()) return checkRange(value_.get<std::int64_t>(), min, max);
        const double value = number();
        if (value != std::floor(value)) fail("must be an integer (got " + formatNumber(value) + ")");
        if (value < double(min) || value > double(max)) fail(rangeProblem(min, max, formatNumber(value)));
        return std::int64_t(value);
    }

    std::string text() const {
        if (!value_.is_string()) failType("a string");
        return value_.get<std::string>();
    }

    // One of a fixed set of names, e.g. {{"center", Sampling::Center}, {"corner", Sampling::Corner}}.
    template <class Enum, std::size_t N>
    Enum choice(const std::pair<const char*, Enum> (&options)[N]) const {
        const std::string name = text();
        std::vector<std::string> names;
        for (const auto& [optionName, option] : options) {
            if (name == optionName) return option;
            names.emplace_back(optionName);
        }
        fail("unknown value " + quoted(name) + " (allowed: " + joined(names) + ")");
    }

    // A length (a coordinate, height, radius or size) within the supported range (scene.h).
    double length(bool mayBeZero = true) const {
        const double value = number(mayBeZero ? Bounds{} : kPositive);
        return checkSupported(value, mayBeZero, kMinSceneLength, kMaxSceneLength, "lengths");
    }

    // A light's intensity: an irradiance at distance 1, so the square of a length.
    double intensity() const {
        const double value = number(kNonNegative);
        return checkSupported(value, true, kMinIntensity, kMaxIntensity, "intensities");
    }

    // A point: three lengths.
    glm::dvec3 position() const {
        vec3();  // the shape and finiteness first, with their own messages
        const std::vector<JsonReader> xyz = elements();
        return {xyz[0].length(), xyz[1].length(), xyz[2].length()};
    }

    glm::dvec3 vec3() const {
        if (!value_.is_array() || value_.size() != 3) failType("an array of 3 numbers [x, y, z]");
        const std::vector<JsonReader> xyz = elements();
        return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
    }

    // [r, g, b] (linear, may exceed 1 for HDR) or web hex "#rrggbb" (byte / 255, no gamma).
    Color colour() const {
        static const std::string kForms = "[r, g, b] with finite components >= 0, or \"#rrggbb\"";
        if (value_.is_string()) {
            if (auto parsed = parseHexColour(value_.get<std::string>())) return *parsed;
        } else if (value_.is_array() && value_.size() == 3) {
            Color result;
            for (std::size_t i = 0; i < 3; ++i) {
                const Json& component = value_[i];
                const bool valid = component.is_number() && std::isfinite(component.get<double>()) &&
                                   component.get<double>() >= 0.0;
                if (!valid) {
                    JsonReader(component, source_, elementPath(path_, i))
                        .fail("colour component must be a finite number >= 0 (got " + describe(component) +
                              "); a colour is " + kForms);
                }
                if (component.get<double>() > kMaxColorComponent) {
                    JsonReader(component, source_, elementPath(path_, i))
                        .fail("colour component must be at most " + formatNumber(kMaxColorComponent) +
                              ", the supported range (got " + describe(component) + ")");
                }
                result[int(i)] = component.get<double>();
            }
            return result;
        }
        fail("expected a colour: " + kForms + " (got " + describe(value_) + ")");
    }

    // ---- optional fields with defaults

    double numberOr(const std::string& key, double fallback, const Bounds& bounds = {}) const {
        const auto found = find(key);
        return found ? found->number(bounds) : fallback;
    }

    Color colourOr(const std::string& key, Color fallback) const {
        const auto found = find(key);
        return found ? found->colour() : fallback;
    }

    template <class Enum, std::size_t N>
    Enum choiceOr(const std::string& key, Enum fallback, const std::pair<const char*, Enum> (&options)[N]) const {
        const auto found = find(key);
        return found ? found->choice(options) : fallback;
    }

private:
    JsonReader child(const std::string& key, const Json& value) const {
        return JsonReader(value, source_, childPath(path_, key));
    }

    [[noreturn]] void failType(const std::string& expected) const {
        fail("expected " + expected + " (got " + describe(value_) + ")");
    }

    double checkSupported(double value, bool mayBeZero, double min, double max, const std::string& what) const {
        const double magnitude = std::fabs(value);
        if ((mayBeZero && value == 0.0) || (magnitude >= min && magnitude <= max)) return value;
        fail(std::string("must be ") + (mayBeZero ? "0 or " : "") + "between " + formatNumber(min) + " and " +
             formatNumber(max) + " in magnitude, the supported range of " + what + " (got " + formatNumber(value) +
             ")");
    }

    std::int64_t checkRange(std::int64_t value, std::int64_t min, std::int64_t max) const {
        if (value < min || value > max) fail(rangeProblem(min, max, std::to_string(value)));
        return value;
    }

    static std::optional<Color> parseHexColour(const std::string& text) {
        if (text.size() != 7 || text[0] != '#') return std::nullopt;
        Color result;
        for (int channel = 0; channel < 3; ++channel) {
            unsigned byte = 0;
            const char* first = text.data() + 1 + 2 * channel;
            const auto parsed = std::from_chars(first, first + 2, byte, 16);  // accepts either case
            if (parsed.ec != std::errc() || parsed.ptr != first + 2) return std::nullopt;
            result[channel] = double(byte) / 255.0;
        }
        return result;
    }

    const Json& value_;
    const std::string& source_;
    std::string path_;
};

// ---------------------------------------------------------------- the scene, part by part

constexpr std::pair<const char*, Sampling> kSamplingNames[] = {{"center", Sampling::Center},
                                                               {"corner", Sampling::Corner}};
constexpr std::pair<const char*, Encoding> kEncodingNames[] = {{"srgb", Encoding::Srgb},
                                                               {"linear", Encoding::Linear}};

enum class GeometryType { Plane, Sphere };
constexpr std::pair<const char*, GeometryType> kGeometryTypes[] = {{"plane", GeometryType::Plane},
                                                                   {"sphere", GeometryType::Sphere}};

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

CameraSettings readCamera(const JsonReader& camera) {
    camera.rejectUnknownKeys({"position", "yaw", "pitch", "roll", "fov", "aspect"});
    CameraSettings settings;  // its defaults are the format's defaults
    settings.position = camera.at("position").position();
    settings.yawDegrees = camera.numberOr("yaw", settings.yawDegrees);
    settings.pitchDegrees = camera.numberOr("pitch", settings.pitchDegrees);
    settings.rollDegrees = camera.numberOr("roll", settings.rollDegrees);
    settings.fovDegrees = camera.numberOr("fov", settings.fovDegrees, Bounds{.above = 0.0, .below = 180.0});
    if (auto aspect = camera.find("aspect")) settings.aspect = aspect->number(kPositive);
    return settings;
}

PointLight readLight(const JsonReader& light) {
    light.rejectUnknownKeys({"position", "color", "intensity"});
    PointLight result;
    result.position = light.at("position").position();
    result.color = light.colourOr("color", result.color);
    result.intensity = light.at("intensity").intensity();
    return result;
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
    if (type == ShaderType::Constant) return ConstantShader{color};
    return LambertShader{color};
}

Geometry readGeometry(const JsonReader& geometry) {
    const GeometryType type = geometry.at("type").choice(kGeometryTypes);
    if (type == GeometryType::Plane) {
        geometry.rejectUnknownKeys({"type", "y"});
        return Plane{geometry.at("y").length()};
    }
    geometry.rejectUnknownKeys({"type", "center", "radius"});
    return Sphere{geometry.at("center").position(), geometry.at("radius").length(false)};
}

std::uint32_t readShaderReference(const JsonReader& reference, const std::vector<std::string>& shaderNames) {
    const std::string name = reference.text();
    const auto found = std::find(shaderNames.begin(), shaderNames.end(), name);
    if (found == shaderNames.end()) {
        reference.fail("unknown shader " + quoted(name) +
                       (shaderNames.empty() ? " (no shaders are defined)" : " (defined: " + joined(shaderNames) + ")"));
    }
    return std::uint32_t(found - shaderNames.begin());
}

Node readNode(const JsonReader& node, const std::vector<std::string>& shaderNames) {
    node.rejectUnknownKeys({"geometry", "shader"});
    return Node{readGeometry(node.at("geometry")), readShaderReference(node.at("shader"), shaderNames)};
}

Scene readScene(const JsonReader& root) {
    root.rejectUnknownKeys({"image", "camera", "background", "ambient", "lights", "shaders", "nodes"});
    Scene scene;
    scene.image = readImage(root.at("image"));
    scene.camera = readCamera(root.at("camera"));
    scene.background = root.colourOr("background", scene.background);
    scene.ambient = root.colourOr("ambient", scene.ambient);
    if (auto lights = root.find("lights")) {
        for (const JsonReader& light : lights->elements()) scene.lights.push_back(readLight(light));
    }
    if (auto shaders = root.find("shaders")) {
        for (const auto& [name, shader] : shaders->members()) {
            scene.shaderNames.push_back(name);
            scene.shaders.push_back(readShader(shader));
        }
    }
    for (const JsonReader& node : root.at("nodes").elements()) scene.nodes.push_back(readNode(node, scene.shaderNames));
    return scene;
}

// ---------------------------------------------------------------- parsing the text

// Follows the parser through the document, so that problems the parser itself meets
// (a duplicate key, a number too large for a double, absurd nesting) can be reported at
// their JSON path. Paths are built only for a message: storing one per level would make
// deep nesting cost quadratic time and memory (20 KB of '[' took a minute and 1.4 GB).
class ParsePathTracker {
public:
    explicit ParsePathTracker(const std::string& source) : source_(source) {}

    // nlohmann's parser callback; always keeps the value.
    bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                // Scene files nest 5 levels deep; anything far deeper is not a scene.
                if (frames_.size() >= kMaxNesting) {
                    throw SceneError(source_ + ": " + displayPath(pendingPath()) + ": nested deeper than " +
                                     std::to_string(kMaxNesting) + " levels");
                }
                startValue();
                frames_.push_back(Frame{event == Json::parse_event_t::array_start, 0, {}, {}});
                break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                frames_.pop_back();
                break;
            case Json::parse_event_t::key: {
                Frame& object = frames_.back();
                object.currentKey = parsed.get<std::string>();
                // nlohmann keeps the last of duplicate keys; the earlier one would silently vanish.
                if (!object.keys.insert(object.currentKey).second) {
                    throw SceneError(source_ + ": " + pendingPath() + ": duplicate key");
                }
                break;
            }
            case Json::parse_event_t::value:
                startValue();
                break;
        }
        return true;
    }

    // Where the value the parser is reading now (and has not yet reported) belongs.
    std::string pendingPath() const {
        std::string path;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const Frame& frame = frames_[i];
            // An array's index has already moved past the elements its open children are in.
            const bool pending = i + 1 == frames_.size();
            path = frame.isArray ? elementPath(path, frame.nextIndex - (pending ? 0 : 1))
                                 : childPath(path, frame.currentKey);
        }
        return path;
    }

private:
    static constexpr std::size_t kMaxNesting = 64;

    struct Frame {
        bool isArray = false;
        std::size_t nextIndex = 0;  // arrays: index of the next element
        std::string currentKey;     // objects: key of the value being read
        std::set<std::string> keys;
    };

    // The pending value has begun: an array's next one gets the next index.
    void startValue() {
        if (!frames_.empty() && frames_.back().isArray) ++frames_.back().nextIndex;
    }

    const std::string& source_;
    std::vector<Frame> frames_;
};

// nlohmann reports the byte offset (1-based) of the last character it read; people want
// line:column. Columns count characters (UTF-8 code points), not bytes.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
    const std::size_t offset = std::min(byte == 0 ? 0 : byte - 1, text.size());
    std::size_t line = 1;
    std::size_t column = 1;
    const std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a BOM takes no column
    for (std::size_t i = std::min(start, offset); i < offset; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

// "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..." -> "syntax error ...".
std::string parseErrorDetail(const std::string& what) {
    const std::size_t errorAt = what.find("parse error");
    if (errorAt == std::string::npos) return what;
    const std::size_t colon = what.find(": ", errorAt);
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    // nlohmann quotes the whole token it stopped in ("last read: '...'"), which may be a huge string.
    const std::string kLastRead = "last read: '";
    const std::size_t tokenStart = detail.find(kLastRead);
    if (tokenStart == std::string::npos) return detail;
    const std::size_t first = tokenStart + kLastRead.size();
    const std::size_t expected = detail.rfind("'; expected");
    const std::size_t last = expected != std::string::npos && expected >= first ? expected : detail.rfind('\'');
    if (last == std::string::npos || last < first || last - first <= kMaxShown) return detail;
    std::size_t cut = first + kMaxShown;
    while (cut > first && (static_cast<unsigned char>(detail[cut]) & 0xC0) == 0x80) --cut;  // whole UTF-8 characters
    return detail.substr(0, cut) + "..." + detail.substr(last);
}

// "[json.exception.out_of_range.406] number overflow parsing '1e999'" -> "1e999".
std::string overflowingLiteral(const std::string& what) {
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    if (open == std::string::npos || close <= open) return "a number too large for a double";
    return what.substr(open + 1, close - open - 1);
}

[[noreturn]] void failToRead(const std::filesystem::path& path, int error) {
    throw SceneError(path.string() + ": cannot read scene file: " + std::strerror(error));
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& sourceName) {
    ParsePathTracker tracker(sourceName);
    Json document;
    try {
        document = Json::parse(text, std::ref(tracker));
    } catch (const Json::parse_error& error) {
        throw SceneError(sourceName + ":" + lineAndColumn(text, error.byte) +
                         ": JSON syntax error: " + parseErrorDetail(error.what()));
    } catch (const Json::out_of_range& error) {
        // Thrown for a literal like 1e999 before it reaches the document: name its path here.
        throw SceneError(sourceName + ": " + displayPath(tracker.pendingPath()) +
                         ": must be a finite number (got " + overflowingLiteral(error.what()) + ")");
    }
    return readScene(JsonReader(document, sourceName, ""));
}

Scene loadSceneFile(const std::filesystem::path& path) {
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) failToRead(path, EISDIR);  // fopen would accept it

    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) failToRead(path, errno);
    std::string text;
    char buffer[1 << 16];
    while (const std::size_t count = std::fread(buffer, 1, sizeof buffer, file.get())) {
        text.append(buffer, count);
        if (text.size() > kMaxSceneFileBytes) {
            throw SceneError(path.string() + ": cannot read scene file: larger than " +
                             std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
        }
    }
    if (std::ferror(file.get())) failToRead(path, errno);
    return parseScene(text, path.string());
}

void overrideImageSize(Scene& scene, std::int64_t width, std::int64_t height, const std::string& source) {
    // `source` may already name the dimension (e.g. "--width"); otherwise the message must.
    const auto checkDimension = [&](std::int64_t value, const std::string& dimension, const std::string& other) {
        if (value >= 1 && value <= std::int64_t{kMaxImageDimension}) return;
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

}  // namespace hexray
