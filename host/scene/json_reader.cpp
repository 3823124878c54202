#include "scene/json_reader.h"

#include <algorithm>
#include <charconv>

#include "util/closest_name.h"

namespace hexray::inline scene {

std::string formatNumber(double value) {
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "infinity" : "-infinity";
    const double magnitude = std::fabs(value);
    const bool everyday = magnitude == 0.0 || (magnitude >= 1e-4 && magnitude < 1e15);
    char buffer[64];
    const auto result = everyday ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                                 : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string joined(std::vector<std::string> items, bool sorted) {
    if (sorted)
        std::sort(items.begin(), items.end());
    std::string result;
    for (const std::string& item : items) {
        if (!result.empty())
            result += ", ";
        result += item;
    }
    return result;
}

std::string describe(const Json& value) {
    switch (value.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return value.get<bool>() ? "boolean true" : "boolean false";
        case Json::value_t::string:
            return "string " + quotedForMessage(value.get<std::string>());
        case Json::value_t::number_integer:
            return "number " + std::to_string(value.get<std::int64_t>());
        case Json::value_t::number_unsigned:
            return "number " + std::to_string(value.get<std::uint64_t>());
        case Json::value_t::number_float:
            return "number " + formatNumber(value.get<double>());
        case Json::value_t::array:
            return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
        case Json::value_t::object:
            return "an object";
        default:
            return "an unsupported value";
    }
}

std::string rangeProblem(std::int64_t min, std::int64_t max, const std::string& got) {
    return "must be between " + std::to_string(min) + " and " + std::to_string(max) + " (got " + got + ")";
}

std::string suggestion(const std::string& typed, const std::vector<std::string>& known) {
    std::vector<std::string> sorted = known;  // ties go to the first in the order messages list them
    std::sort(sorted.begin(), sorted.end());
    const std::optional<std::string> closest = closestName(typed, sorted);
    return closest ? "; did you mean " + quotedForMessage(*closest) + "?" : "";
}

}  // namespace hexray::scene
