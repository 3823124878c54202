#include "cli/pixel_record.h"

#include <cmath>
#include <cstdint>

#include "cli/json_document.h"
#include "cli/named_values.h"
#include "cpu/cpu_margins.h"
#include "image/image_io.h"

namespace hexray::cli {
namespace {

using nlohmann::json;

json vec3(const glm::dvec3& v) {
    return json::array({jsonNumber(v.x), jsonNumber(v.y), jsonNumber(v.z)});
}

json jsonLevels(const glm::dvec3& linear, Encoding encoding) {
    return json::array({encodeChannel(float(linear.x), encoding), encodeChannel(float(linear.y), encoding),
                        encodeChannel(float(linear.z), encoding)});
}

const char* lightStatusName(std::uint32_t status) {
    switch (status) {
        case gpu::TRACE_LIGHT_LIT:
            return "lit";
        case gpu::TRACE_LIGHT_FACING_AWAY:
            return "facing_away";
        case gpu::TRACE_LIGHT_SHADOWED:
            return "shadowed";
        case gpu::TRACE_LIGHT_AT_POINT:
            return "at_point";
        default:
            return "not_evaluated";
    }
}

const char* lightReachName(LightReach reach) {
    switch (reach) {
        case LightReach::Lit:
            return "lit";
        case LightReach::FacingAway:
            return "facing_away";
        case LightReach::Shadowed:
            return "shadowed";
        case LightReach::AtPoint:
            return "at_point";
    }
    return "not_evaluated";
}

json light(std::size_t index, const char* status, double cosTheta, double distanceSquared,
           const glm::dvec3& contribution) {
    const bool evaluated = std::string(status) != "not_evaluated";
    return {{"light", index},
            {"status", status},
            {"cos_theta", evaluated ? jsonNumber(cosTheta) : json(nullptr)},
            {"distance_squared", evaluated ? jsonNumber(distanceSquared) : json(nullptr)},
            {"contribution", evaluated ? vec3(contribution) : json(nullptr)}};
}

json pixelClass(std::uint32_t node, std::uint32_t flags) {
    return {{"node", node == PixelClass::kBackground ? json(nullptr) : json(node)}, {"flags", flags}};
}

// The nodes whose intersection the ray found, and how many others it missed.
void addCandidates(json& trace, const Scene& scene, const auto& distanceOf) {
    json candidates = json::array();
    std::size_t missed = 0;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const double t = distanceOf(i);
        if (std::isinf(t)) {
            ++missed;
            continue;
        }
        candidates.push_back({{"node", i}, {"geometry", geometryName(scene.nodes[i].geometry)}, {"t", jsonNumber(t)}});
    }
    trace["candidates"] = std::move(candidates);
    trace["candidates_missed"] = missed;
}

// The hit's surface; `checker` is the node's checker account (null for other shaders).
json hit(const Scene& scene, std::size_t node, double t, const glm::dvec3& position, const glm::dvec3& normal,
         const glm::dvec3& albedo, json checker) {
    const Node& hitNode = scene.nodes.at(node);
    return {{"node", node},           {"geometry", geometryName(hitNode.geometry)},
            {"t", jsonNumber(t)},     {"position", vec3(position)},
            {"normal", vec3(normal)}, {"shader", shaderTypeName(scene.shaders.at(hitNode.shaderIndex))},
            {"albedo", vec3(albedo)}, {"checker", std::move(checker)}};
}

bool checkerShaded(const Scene& scene, std::size_t node) {
    return std::holds_alternative<CheckerShader>(scene.shaders.at(scene.nodes.at(node).shaderIndex));
}

json shaderTrace(const Scene& scene, const GpuPixelTrace& shader) {
    json trace = {{"ray", {{"origin", vec3(shader.rayOrigin)}, {"direction", vec3(shader.rayDirection)}}}};
    addCandidates(trace, scene, [&](std::size_t i) { return shader.candidates.at(i); });
    trace["hit"] = nullptr;
    if (shader.node != PixelClass::kBackground) {
        const bool odd = (shader.flags & PixelClass::kOddCheckerBit) != 0;
        json checker = checkerShaded(scene, shader.node) ? json{{"odd", odd}, {"cell", nullptr}} : json(nullptr);
        trace["hit"] = hit(scene, shader.node, shader.t, shader.position, shader.normal, glm::dvec3(shader.albedo),
                           std::move(checker));
    }
    json lights = json::array();
    for (std::size_t i = 0; i < shader.lights.size(); ++i) {
        const GpuTraceLight& term = shader.lights[i];
        lights.push_back(
            light(i, lightStatusName(term.status), term.cosTheta, term.distanceSquared, glm::dvec3(term.contribution)));
    }
    trace["lights"] = std::move(lights);
    trace["sample_colour"] = vec3(glm::dvec3(shader.sampleColor));
    trace["pixel_colour"] = vec3(glm::dvec3(shader.pixelColor));
    trace["pixel_8bit"] = jsonLevels(glm::dvec3(shader.pixelColor), scene.image.encoding);
    trace["class"] = pixelClass(shader.node, shader.flags);
    return trace;
}

json referenceTrace(const Scene& scene, const CpuPixelExplanation& reference) {
    json trace = {{"ray", {{"origin", vec3(reference.ray.origin)}, {"direction", vec3(reference.ray.direction)}}}};
    addCandidates(trace, scene, [&](std::size_t i) {
        const std::optional<Hit>& candidate = reference.candidates.at(i);
        return candidate ? candidate->t : INFINITY;
    });
    trace["hit"] = nullptr;
    if (reference.nearest) {
        const SceneHit& nearest = *reference.nearest;
        json checker = nullptr;
        if (reference.checkerCell) {
            checker = {{"odd", (reference.pixelClass.flags & PixelClass::kOddCheckerBit) != 0},
                       {"cell", {reference.checkerCell->x, reference.checkerCell->y}}};
        }
        trace["hit"] = hit(scene, nearest.nodeIndex, nearest.hit.t, nearest.hit.point, nearest.hit.facingNormal,
                           reference.albedo, std::move(checker));
    }
    json lights = json::array();
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (i >= reference.lights.size()) {
            lights.push_back(light(i, "not_evaluated", 0, 0, glm::dvec3(0)));
            continue;
        }
        const LightTerm& term = reference.lights[i];
        lights.push_back(light(i, lightReachName(term.decision.reach), term.decision.cosTheta,
                               term.decision.distanceSquared, term.contribution));
    }
    trace["lights"] = std::move(lights);
    trace["sample_colour"] = vec3(reference.sampleColor);
    trace["pixel_colour"] = vec3(reference.pixelColor);
    trace["pixel_8bit"] = jsonLevels(reference.pixelColor, scene.image.encoding);
    trace["class"] = pixelClass(reference.pixelClass.node, reference.pixelClass.flags);
    return trace;
}

json requested(const PixelOptions& options) {
    return {{"backend", nameOf(kPixelBackendNames, options.backend)},
            {"precision", std::string(precisionName(options.precision))},
            {"width", options.image.width ? json(*options.image.width) : json(nullptr)},
            {"height", options.image.height ? json(*options.image.height) : json(nullptr)},
            {"spp", options.image.samplesPerPixel ? json(*options.image.samplesPerPixel) : json(nullptr)}};
}

json gpuSide(const Scene& scene, const GpuPixelTrace& shader) {
    return {{"precision", std::string(precisionName(shader.precision))},
            {"camera_relative", shader.cameraRelative},
            {"length_scale", jsonNumber(shader.scale)},
            {"candidate_lists", shader.usedCandidateLists},
            {"traced_again_in_f64", shader.tracedAgainInF64},
            {"trace", shaderTrace(scene, shader)}};
}

json cpuSide(const Scene& scene, const CpuPixelExplanation& reference, std::optional<double> margin) {
    return {{"decision_margin", jsonNumber(margin)},
            {"ambiguous", margin ? json(*margin < kAmbiguityMargin) : json(nullptr)},
            {"trace", referenceTrace(scene, reference)}};
}

}  // namespace

const char* geometryName(const Geometry& geometry) {
    return std::holds_alternative<Plane>(geometry) ? "plane" : "sphere";
}

const char* shaderTypeName(const Shader& shader) {
    return std::holds_alternative<ConstantShader>(shader)  ? "constant"
           : std::holds_alternative<LambertShader>(shader) ? "lambert"
                                                           : "checker";
}

nlohmann::json pixelDocument(const PixelOptions& options, const PixelRecord& record) {
    json document = jsonDocument("pixel");
    const Scene* scene = record.scene ? &*record.scene : nullptr;
    document["scene"] = options.scenePath;
    document["x"] = options.x;
    document["y"] = options.y;
    document["sample"] = options.sample;
    document["width"] = scene ? json(scene->image.width) : json(nullptr);
    document["height"] = scene ? json(scene->image.height) : json(nullptr);
    document["spp"] = scene ? json(scene->image.samplesPerPixel) : json(nullptr);
    document["encoding"] = scene ? json(scene->image.encoding == Encoding::Srgb ? "srgb" : "linear") : json(nullptr);
    document["requested"] = requested(options);
    document["device"] = record.device ? jsonDevice(*record.device) : json(nullptr);
    document["timings_ms"] = {{"startup", jsonNumber(record.startupMilliseconds)},
                              {"gpu_trace", jsonNumber(record.gpuTraceMilliseconds)},
                              {"cpu_explain", jsonNumber(record.cpuExplainMilliseconds)}};
    document["gpu"] = scene && record.shader ? gpuSide(*scene, *record.shader) : json(nullptr);
    document["cpu"] = scene && record.reference ? cpuSide(*scene, *record.reference, record.margin) : json(nullptr);
    document["comparison"] = nullptr;
    if (record.comparison) {
        const PixelComparison& comparison = *record.comparison;
        document["comparison"] = {{"agree", comparison.differingRows.empty() && !comparison.classDiffers},
                                  {"differing_rows", comparison.differingRows},
                                  {"class_differs", comparison.classDiffers}};
    }
    return document;
}

}  // namespace hexray::cli
