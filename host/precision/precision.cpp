#include "precision/precision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "util/parallel_parts.h"

namespace hexray::inline precision {
namespace {

constexpr std::array<std::pair<Precision, std::string_view>, 5> kNames = {{
    {Precision::Auto, "auto"},
    {Precision::F32Naive, "f32-naive"},
    {Precision::F32, "f32"},
    {Precision::F64, "f64"},
    {Precision::F32Certified, "f32-certified"},
}};

void addLength(MagnitudeRange& range, double length) {
    if (length > 0) {
        range.smallest = std::min(range.smallest, length);
        range.largest = std::max(range.largest, length);
    }
}

void addMagnitudes(MagnitudeRange& range, const Scene& scene, const Node& node, const glm::dvec3& eye) {
    if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
        const double centerDistance = glm::length(sphere->center - eye);
        addLength(range, sphere->radius);
        addLength(range, std::abs(centerDistance - sphere->radius));
        addLength(range, centerDistance + sphere->radius);
    } else {
        addLength(range, std::abs(std::get<Plane>(node.geometry).height - eye.y));
        if (const auto* checker = std::get_if<CheckerShader>(&scene.shaders[node.shaderIndex])) {
            addLength(range, checker->size);
        }
    }
}

void addConditioning(Conditioning& conditioning, const Scene& scene, const Node& node, const glm::dvec3& eye) {
    if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
        const double centerDistance = glm::length(sphere->center - eye);
        conditioning.largestDistance = std::max(conditioning.largestDistance, centerDistance + sphere->radius);
        conditioning.smallestFeature = std::min(conditioning.smallestFeature, sphere->radius);
        // The eye's clearance from the surface: near a large sphere the hit points along
        // the horizon come from differences of numbers as large as the radius.
        const double clearance = std::abs(centerDistance - sphere->radius);
        if (clearance > 0) {
            conditioning.smallestFeature = std::min(conditioning.smallestFeature, clearance);
        }
    } else {
        // A plane reaches the horizon, but what the shader must resolve there is already
        // smaller than a pixel: its height above the eye is the distance that matters.
        conditioning.largestDistance =
            std::max(conditioning.largestDistance, std::abs(std::get<Plane>(node.geometry).height - eye.y));
        if (const auto* checker = std::get_if<CheckerShader>(&scene.shaders[node.shaderIndex])) {
            conditioning.smallestFeature = std::min(conditioning.smallestFeature, checker->size);
        }
    }
}

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
    const Conditioning none{0.0, std::numeric_limits<double>::infinity()};
    Conditioning conditioning = reduceAcrossCores(
        scene.nodes.size(), kNodesPerPart, none,
        [&](Conditioning& part, std::size_t i) { addConditioning(part, scene, scene.nodes[i], eye); },
        [](Conditioning& total, const Conditioning& part) {
            total.largestDistance = std::max(total.largestDistance, part.largestDistance);
            total.smallestFeature = std::min(total.smallestFeature, part.smallestFeature);
        });
    for (const PointLight& light : scene.lights) {
        conditioning.largestDistance = std::max(conditioning.largestDistance, glm::length(light.position - eye));
    }
    if (!std::isfinite(conditioning.smallestFeature)) {
        conditioning.smallestFeature = 0.0;
    }
    return conditioning;
}

MagnitudeRange sceneMagnitudes(const Scene& scene) {
    const glm::dvec3 eye = scene.camera.position;
    const MagnitudeRange none{std::numeric_limits<double>::infinity(), 0.0};
    MagnitudeRange range = reduceAcrossCores(
        scene.nodes.size(), kNodesPerPart, none,
        [&](MagnitudeRange& part, std::size_t i) { addMagnitudes(part, scene, scene.nodes[i], eye); },
        [](MagnitudeRange& total, const MagnitudeRange& part) {
            total.smallest = std::min(total.smallest, part.smallest);
            total.largest = std::max(total.largest, part.largest);
        });
    for (const PointLight& light : scene.lights) {
        addLength(range, glm::length(light.position - eye));
        addLength(range, std::sqrt(light.intensity * std::max({light.color.r, light.color.g, light.color.b})));
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
