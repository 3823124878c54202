#include "precision/precision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

namespace hexray::inline precision {
namespace {

constexpr std::array<std::pair<Precision, std::string_view>, 5> kNames = {{
    {Precision::Auto, "auto"},
    {Precision::F32Naive, "f32-naive"},
    {Precision::F32, "f32"},
    {Precision::F64, "f64"},
    {Precision::F32Certified, "f32-certified"},
}};

}  // namespace

std::string_view precisionName(Precision precision) {
    for (const auto& [value, name] : kNames) {
        if (value == precision) {
            return name;
        }
    }
    return "?";
}

std::optional<Precision> parsePrecision(std::string_view name) {
    for (const auto& [value, known] : kNames) {
        if (known == name) {
            return value;
        }
    }
    return std::nullopt;
}

Conditioning estimateConditioning(const Scene& scene) {
    const glm::dvec3 eye = scene.camera.position;
    Conditioning conditioning;
    double smallest = std::numeric_limits<double>::infinity();
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            const double centerDistance = glm::length(sphere->center - eye);
            conditioning.largestDistance = std::max(conditioning.largestDistance, centerDistance + sphere->radius);
            smallest = std::min(smallest, sphere->radius);
            // The eye's clearance from the surface: near a large sphere the hit points along
            // the horizon come from differences of numbers as large as the radius.
            const double clearance = std::abs(centerDistance - sphere->radius);
            if (clearance > 0) {
                smallest = std::min(smallest, clearance);
            }
        } else {
            // A plane reaches the horizon, but what the shader must resolve there is already
            // smaller than a pixel: its height above the eye is the distance that matters.
            conditioning.largestDistance =
                std::max(conditioning.largestDistance, std::abs(std::get<Plane>(node.geometry).height - eye.y));
            if (const auto* checker = std::get_if<CheckerShader>(&scene.shaders[node.shaderIndex])) {
                smallest = std::min(smallest, checker->size);
            }
        }
    }
    for (const PointLight& light : scene.lights) {
        conditioning.largestDistance = std::max(conditioning.largestDistance, glm::length(light.position - eye));
    }
    conditioning.smallestFeature = std::isfinite(smallest) ? smallest : 0.0;
    return conditioning;
}

MagnitudeRange sceneMagnitudes(const Scene& scene) {
    const glm::dvec3 eye = scene.camera.position;
    MagnitudeRange range{std::numeric_limits<double>::infinity(), 0.0};
    const auto add = [&range](double length) {
        if (length > 0) {
            range.smallest = std::min(range.smallest, length);
            range.largest = std::max(range.largest, length);
        }
    };
    for (const Node& node : scene.nodes) {
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            const double centerDistance = glm::length(sphere->center - eye);
            add(sphere->radius);
            add(std::abs(centerDistance - sphere->radius));
            add(centerDistance + sphere->radius);
        } else {
            add(std::abs(std::get<Plane>(node.geometry).height - eye.y));
            if (const auto* checker = std::get_if<CheckerShader>(&scene.shaders[node.shaderIndex])) {
                add(checker->size);
            }
        }
    }
    for (const PointLight& light : scene.lights) {
        add(glm::length(light.position - eye));
        add(std::sqrt(light.intensity * std::max({light.color.r, light.color.g, light.color.b})));
    }
    return range.largest > 0 ? range : MagnitudeRange{};
}

std::optional<std::string> float32RangeProblem(const Scene& scene) {
    const MagnitudeRange range = sceneMagnitudes(scene);
    if (range.ratio() <= kFloat32MagnitudeRatio) {
        return std::nullopt;
    }
    char reason[160];
    std::snprintf(reason, sizeof reason, "its lengths span %.3g to %.3g, a ratio beyond float32's 2^100",
                  range.smallest, range.largest);
    return reason;
}

Precision choosePrecision(const Scene& scene, bool deviceHasFloat64) {
    const bool float32Suffices =
        estimateConditioning(scene).ratio() <= kFloat32ConditioningLimit && !float32RangeProblem(scene);
    return float32Suffices || !deviceHasFloat64 ? Precision::F32 : Precision::F64;
}

}  // namespace hexray::precision
