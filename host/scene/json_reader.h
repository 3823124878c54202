#pragma once
// Reading a scene file's JSON document: values checked as the format requires, each rejection a
// SceneError that names the source and the value's path.

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/hex_colour.h"
#include "scene/json_path.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"

namespace hexray::inline scene {

using Json = nlohmann::json;

// Shortest round trip; plain digits for everyday magnitudes, so 1e6 reads as 1000000.
std::string formatNumber(double value);

// "a, b, c", sorted unless asked not to.
std::string joined(std::vector<std::string> items, bool sorted = true);

// What a value is, for "expected X (got Y)" messages.
std::string describe(const Json& value);

std::string rangeProblem(std::int64_t min, std::int64_t max, const std::string& got);

// "; did you mean \"color\"?" when one of `known` is close to `typed` (util/closest_name.h), else "".
std::string suggestion(const std::string& typed, const std::vector<std::string>& known);

// Bounds a number must respect; the message spells out the ones given.
struct Bounds {
    std::optional<double> above = std::nullopt;    // exclusive lower bound
    std::optional<double> atLeast = std::nullopt;  // inclusive lower bound
    std::optional<double> below = std::nullopt;    // exclusive upper bound
};
inline const Bounds kPositive{.above = 0.0};
inline const Bounds kNonNegative{.atLeast = 0.0};

// One JSON value at a known place in a known source. The typed getters check the value and
// throw SceneError naming source and path, so the scene code reads as a description. A
// value's path is spelled out only for a message: a million nodes need no million paths.
class JsonReader {
public:
    JsonReader(const Json& value, const std::string& source, std::string path)
        : value_(value), source_(source), path_(std::move(path)) {}

    // The element `index` of the array `parent` reads (which must outlive it).
    JsonReader(const Json& value, const JsonReader& parent, std::size_t index)
        : value_(value), source_(parent.source_), parent_(&parent), index_(index) {}

    [[noreturn]] void fail(const std::string& reason) const {
        throw SceneError(source_ + ": " + displayPath(path()) + ": " + reason);
    }

    std::string path() const {
        if (!parent_)
            return path_;
        return key_ ? childPath(parent_->path(), *key_) : elementPath(parent_->path(), index_);
    }

    // ---- objects

    void expectObject() const {
        if (!value_.is_object())
            failType("an object");
    }

    // A typo must not be silently ignored: every key must be one the format knows here.
    void rejectUnknownKeys(std::initializer_list<std::string_view> allowed) const {
        expectObject();
        for (const auto& [key, value] : value_.items()) {
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
                const std::vector<std::string> known(allowed.begin(), allowed.end());
                child(key, value).fail("unknown key (allowed: " + joined(known) + ")" + suggestion(key, known));
            }
        }
    }

    JsonReader at(std::string_view key) const {
        if (auto found = find(key))
            return *found;
        JsonReader(Json(), source_, childPath(path(), std::string(key))).fail("missing required field");
    }

    std::optional<JsonReader> find(std::string_view key) const {
        expectObject();
        const auto found = value_.find(key);
        if (found == value_.end())
            return std::nullopt;
        return child(found.key(), *found);
    }

    // nlohmann keeps objects sorted by key, so the order does not depend on how the file is laid out.
    std::vector<std::pair<std::string, JsonReader>> members() const {
        expectObject();
        std::vector<std::pair<std::string, JsonReader>> result;
        for (const auto& [key, value] : value_.items())
            result.emplace_back(key, child(key, value));
        return result;
    }

    // ---- arrays

    void expectArray() const {
        if (!value_.is_array())
            failType("an array");
    }

    std::vector<JsonReader> elements() const {
        expectArray();
        std::vector<JsonReader> result;
        for (std::size_t i = 0; i < value_.size(); ++i) {
            result.emplace_back(value_[i], *this, i);
        }
        return result;
    }

    // ---- scalars

    double number(const Bounds& bounds = {}) const {
        if (!value_.is_number())
            failType("a number");
        const double value = value_.get<double>();
        if (!std::isfinite(value))
            fail("must be a finite number (got " + formatNumber(value) + ")");
        const bool tooLow =
            (bounds.above && !(value > *bounds.above)) || (bounds.atLeast && !(value >= *bounds.atLeast));
        const bool tooHigh = bounds.below && !(value < *bounds.below);
        if (tooLow || tooHigh) {
            std::vector<std::string> rules;
            if (bounds.above)
                rules.push_back("> " + formatNumber(*bounds.above));
            if (bounds.atLeast)
                rules.push_back(">= " + formatNumber(*bounds.atLeast));
            if (bounds.below)
                rules.push_back("< " + formatNumber(*bounds.below));
            std::string rule;
            for (const std::string& part : rules)
                rule += (rule.empty() ? "" : " and ") + part;
            fail("must be " + rule + " (got " + formatNumber(value) + ")");
        }
        return value;
    }

    // JSON has one number type, so 800.0 counts as an integer but 800.5 does not.
    std::int64_t integer(std::int64_t min, std::int64_t max) const {
        if (!value_.is_number())
            failType("an integer");
        if (value_.is_number_unsigned()) {
            const std::uint64_t value = value_.get<std::uint64_t>();
            if (value > std::uint64_t(max))
                fail(rangeProblem(min, max, std::to_string(value)));
            return checkRange(std::int64_t(value), min, max);
        }
        if (value_.is_number_integer())
            return checkRange(value_.get<std::int64_t>(), min, max);
        const double value = number();
        if (value != std::floor(value))
            fail("must be an integer (got " + formatNumber(value) + ")");
        if (value < double(min) || value > double(max))
            fail(rangeProblem(min, max, formatNumber(value)));
        return std::int64_t(value);
    }

    std::string text() const {
        if (!value_.is_string())
            failType("a string");
        return value_.get<std::string>();
    }

    // One of a fixed set of names, e.g. {{"center", Sampling::Center}, {"corner", Sampling::Corner}}.
    template <class Enum, std::size_t N>
    Enum choice(const std::pair<const char*, Enum> (&options)[N]) const {
        const std::string name = text();
        for (const auto& [optionName, option] : options) {
            if (name == optionName)
                return option;
        }
        std::vector<std::string> names;
        for (const auto& [optionName, option] : options)
            names.emplace_back(optionName);
        fail("unknown value " + quotedForMessage(name) + " (allowed: " + joined(names) + ")" + suggestion(name, names));
    }

    glm::dvec3 vec3() const {
        if (!value_.is_array() || value_.size() != 3)
            failType("an array of 3 numbers [x, y, z]");
        const std::vector<JsonReader> xyz = elements();
        return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
    }

    // A length (a coordinate, height, radius or size) within the supported range (scene.h).
    double length(bool mayBeZero = true) const {
        const double value = number(mayBeZero ? Bounds{} : kPositive);
        if (isSupportedLength(value, mayBeZero))
            return value;
        failUnsupported(value, mayBeZero, kMinSceneLength, kMaxSceneLength, "lengths");
    }

    // A light's intensity: an irradiance at distance 1, so the square of a length.
    double intensity() const {
        const double value = number(kNonNegative);
        if (value == 0.0 || (value >= kMinIntensity && value <= kMaxIntensity))
            return value;
        failUnsupported(value, true, kMinIntensity, kMaxIntensity, "intensities");
    }

    // A point: three lengths.
    glm::dvec3 position() const {
        vec3();  // the shape and finiteness first, with their own messages
        const std::vector<JsonReader> xyz = elements();
        return {xyz[0].length(), xyz[1].length(), xyz[2].length()};
    }

    // [r, g, b] (linear, may exceed 1 for HDR) or "#rrggbb" (sRGB as in CSS, linearised: scene/hex_colour.h).
    Color colour() const {
        static const std::string kForms = "[r, g, b] with finite components >= 0, or \"#rrggbb\"";
        if (value_.is_string()) {
            if (auto parsed = parseHexColour(value_.get<std::string>()))
                return *parsed;
        } else if (value_.is_array() && value_.size() == 3) {
            Color result;
            for (std::size_t i = 0; i < 3; ++i) {
                const Json& component = value_[i];
                const bool valid =
                    component.is_number() && std::isfinite(component.get<double>()) && component.get<double>() >= 0.0;
                if (!valid) {
                    JsonReader(component, *this, i)
                        .fail("colour component must be a finite number >= 0 (got " + describe(component) +
                              "); a colour is " + kForms);
                }
                if (component.get<double>() > kMaxColorComponent) {
                    JsonReader(component, *this, i)
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

    double numberOr(std::string_view key, double fallback, const Bounds& bounds = {}) const {
        const auto found = find(key);
        return found ? found->number(bounds) : fallback;
    }

    Color colourOr(std::string_view key, Color fallback) const {
        const auto found = find(key);
        return found ? found->colour() : fallback;
    }

    template <class Enum, std::size_t N>
    Enum choiceOr(std::string_view key, Enum fallback, const std::pair<const char*, Enum> (&options)[N]) const {
        const auto found = find(key);
        return found ? found->choice(options) : fallback;
    }

private:
    // The value of `key`, which must be the document's own copy of the key (it outlives this).
    JsonReader child(const std::string& key, const Json& value) const {
        JsonReader result(value, *this, 0);
        result.key_ = &key;
        return result;
    }

    [[noreturn]] void failType(const std::string& expected) const {
        fail("expected " + expected + " (got " + describe(value_) + ")");
    }

    [[noreturn]] void failUnsupported(double value, bool mayBeZero, double min, double max,
                                      const std::string& what) const {
        fail(std::string("must be ") + (mayBeZero ? "0 or " : "") + "between " + formatNumber(min) + " and " +
             formatNumber(max) + " in magnitude, the supported range of " + what + " (got " + formatNumber(value) +
             ")");
    }

    std::int64_t checkRange(std::int64_t value, std::int64_t min, std::int64_t max) const {
        if (value < min || value > max)
            fail(rangeProblem(min, max, std::to_string(value)));
        return value;
    }

    const Json& value_;
    const std::string& source_;
    std::string path_;                    // without a parent: the whole path
    const JsonReader* parent_ = nullptr;  // with one: the path is the parent's, then
    const std::string* key_ = nullptr;    // this key in an object,
    std::size_t index_ = 0;               // or else this index in an array
};

}  // namespace hexray::scene
