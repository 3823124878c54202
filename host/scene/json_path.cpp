#include "scene/json_path.h"

#include <algorithm>
#include <string_view>

#include <nlohmann/json.hpp>

#include "util/printable.h"

namespace hexray::inline scene {
namespace {

bool isIdentifier(std::string_view key) {
    const auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    return !key.empty() && isLetter(key[0]) &&
           std::all_of(key.begin(), key.end(), [&](char c) { return isLetter(c) || isDigit(c); });
}

}  // namespace

std::string quotedForMessage(const std::string& text) {
    using Json = nlohmann::json;
    const std::string shown = text.size() > kMaxShown ? text.substr(0, kMaxShown) : text;
    std::string result = Json(shown).dump(-1, ' ', false, Json::error_handler_t::replace);
    if (shown.size() < text.size())
        result += "...";
    return printable(result);  // JSON leaves DEL and C1 controls as they are
}

std::string childPath(const std::string& parent, const std::string& key) {
    if (!isIdentifier(key) || key.size() > kMaxShown)
        return parent + "[" + quotedForMessage(key) + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string elementPath(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string displayPath(const std::string& path) {
    return path.empty() ? "(root)" : path;
}

}  // namespace hexray::scene
