#include "scene/scene_settings.h"

#include <cstddef>
#include <variant>

#include <nlohmann/json.hpp>

#include "scene/json_path.h"
#include "scene/scene_json_parser.h"
#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::inline scene {
namespace {

using Json = nlohmann::json;
using Step = std::variant<std::string, std::size_t>;  // an object's key or an array's index

[[noreturn]] void failSetting(const std::string& setting, const std::string& reason) {
    throw SceneError("--set " + printable(setting) + ": " + reason);
}

// `name` or `["any key"]` (a JSON string) after a '.' or at the start, or `[index]`.
std::vector<Step> pathSteps(const std::string& path, const std::string& setting) {
    std::vector<Step> steps;
    std::size_t at = 0;
    while (at < path.size()) {
        if (path[at] == '[') {
            const bool quoted = at + 1 < path.size() && path[at + 1] == '"';
            const std::size_t close = quoted ? path.find("\"]", at + 2) : path.find(']', at);
            if (close == std::string::npos)
                failSetting(setting, "unclosed [ in the path");
            const std::string inside = path.substr(at + 1, close + (quoted ? 1 : 0) - at - 1);
            const Json parsed = Json::parse(inside, nullptr, false);
            if (quoted && parsed.is_string())
                steps.emplace_back(parsed.get<std::string>());
            else if (!quoted && parsed.is_number_unsigned())
                steps.emplace_back(parsed.get<std::size_t>());
            else
                failSetting(setting, "[" + inside + "] is neither an index nor a quoted key");
            at = close + (quoted ? 2 : 1);
        } else {
            if (path[at] == '.' && !steps.empty())
                ++at;
            const std::size_t end = path.find_first_of(".[", at);
            const std::string key = path.substr(at, end == std::string::npos ? std::string::npos : end - at);
            if (key.empty())
                failSetting(setting, "the path has an empty key (keys are joined by '.', indices written [2])");
            steps.emplace_back(key);
            at = end == std::string::npos ? path.size() : end;
        }
    }
    if (steps.empty())
        failSetting(setting, "no path before '=' (e.g. --set camera.fov=60)");
    return steps;
}

// The place `steps` lead to in `document`, made if it is a new key of an existing object.
Json& placeOf(Json& document, const std::vector<Step>& steps, const std::string& setting) {
    Json* value = &document;
    std::string path;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const bool last = i + 1 == steps.size();
        if (const std::string* key = std::get_if<std::string>(&steps[i])) {
            if (!value->is_object())
                failSetting(setting,
                            displayPath(path) + " is not an object (it has no key " + quotedForMessage(*key) + ")");
            if (!last && !value->contains(*key))
                failSetting(setting, childPath(path, *key) + " is not in the scene");
            value = &(*value)[*key];
            path = childPath(path, *key);
        } else {
            const std::size_t index = std::get<std::size_t>(steps[i]);
            if (!value->is_array())
                failSetting(setting, displayPath(path) + " is not an array");
            if (index >= value->size())
                failSetting(setting, displayPath(path) + " has " + std::to_string(value->size()) + " elements");
            value = &(*value)[index];
            path = elementPath(path, index);
        }
    }
    return *value;
}

void applySetting(Json& document, const std::string& setting) {
    const std::size_t equals = setting.find('=');
    if (equals == std::string::npos)
        failSetting(setting, "expected PATH=VALUE, e.g. --set camera.fov=60");
    const std::string valueText = setting.substr(equals + 1);
    Json value = Json::parse(valueText, nullptr, false);
    if (value.is_discarded())
        value = valueText;  // #1a2433, lambert: a string without its quotes
    placeOf(document, pathSteps(setting.substr(0, equals), setting), setting) = std::move(value);
}

}  // namespace

std::string withSettings(const std::string& text, const std::string& source, const std::vector<std::string>& settings) {
    // Read as the loader reads it (syntax errors at line:column, duplicate keys), its streamed
    // arrays collected back into the document.
    Json nodes = Json::array();
    Json lights = Json::array();
    const auto keepNode = [&nodes](const Json& element, std::size_t) { nodes.push_back(element); };
    const auto keepLight = [&lights](const Json& element, std::size_t) { lights.push_back(element); };
    Json document = parseSceneJson(text, printable(source), keepNode, keepLight);
    if (document.is_object() && document.contains("nodes") && document["nodes"].is_array())
        document["nodes"] = std::move(nodes);
    if (document.is_object() && document.contains("lights") && document["lights"].is_array())
        document["lights"] = std::move(lights);
    for (const std::string& setting : settings)
        applySetting(document, setting);
    return document.dump();
}

}  // namespace hexray::scene
