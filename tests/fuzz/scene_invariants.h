#pragma once
// What the renderers assume of every scene the loader accepts. The fuzzer traps on a
// violation; the regression test reports it. Checked independently of the loader's own code.

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include "scene/scene.h"

namespace hexray::test {

namespace invariant_detail {

inline bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool validColour(const Color& c) {
    return finite(c) && c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0 && c.r <= kMaxColorComponent &&
           c.g <= kMaxColorComponent && c.b <= kMaxColorComponent;
}
// The supported range of lengths (scene.h): 0 or a magnitude within [kMinSceneLength, kMaxSceneLength].
inline bool supportedLength(double x) {
    return x == 0.0 || (std::fabs(x) >= kMinSceneLength && std::fabs(x) <= kMaxSceneLength);
}
inline bool supportedPoint(const glm::dvec3& p) {
    return supportedLength(p.x) && supportedLength(p.y) && supportedLength(p.z);
}

}  // namespace invariant_detail

// The first invariant `scene` breaks, or nothing.
inline std::optional<std::string> sceneInvariantViolation(const Scene& scene) {
    using namespace invariant_detail;
    const ImageSettings& image = scene.image;
    if (image.width < 1 || image.width > kMaxImageDimension)
        return "image.width out of range";
    if (image.height < 1 || image.height > kMaxImageDimension)
        return "image.height out of range";
    if (image.samplesPerPixel < 1 || image.samplesPerPixel > kMaxSamplesPerPixel)
        return "image.spp out of range";
    if (std::uint64_t{image.width} * image.height * image.samplesPerPixel > kMaxImageSamples) {
        return "image: more than kMaxImageSamples samples";
    }
    if (image.sampling != Sampling::Center && image.sampling != Sampling::Corner)
        return "image.sampling invalid";
    if (image.encoding != Encoding::Srgb && image.encoding != Encoding::Linear)
        return "image.encoding invalid";

    const CameraSettings& camera = scene.camera;
    if (!finite(camera.position))
        return "camera.position not finite";
    if (!supportedPoint(camera.position))
        return "camera.position outside the supported range";
    if (!std::isfinite(camera.yawDegrees) || !std::isfinite(camera.pitchDegrees) ||
        !std::isfinite(camera.rollDegrees)) {
        return "camera angle not finite";
    }
    if (!(camera.fovDegrees > 0.0 && camera.fovDegrees < 180.0))
        return "camera.fov outside (0, 180)";
    if (camera.aspect && !(std::isfinite(*camera.aspect) && *camera.aspect > 0.0))
        return "camera.aspect not > 0";
    const double aspect = sheetAspect(scene);
    if (!(std::isfinite(aspect) && aspect > 0.0))
        return "sheet aspect not finite and > 0";

    if (!validColour(scene.background))
        return "background not a valid colour";
    if (!validColour(scene.ambient))
        return "ambient not a valid colour";

    for (const PointLight& light : scene.lights) {
        if (!finite(light.position))
            return "light position not finite";
        if (!supportedPoint(light.position))
            return "light position outside the supported range";
        if (light.intensity != 0.0 && !(light.intensity >= kMinIntensity && light.intensity <= kMaxIntensity)) {
            return "light intensity outside the supported range";
        }
        if (!validColour(light.color))
            return "light colour invalid";
        if (!(std::isfinite(light.intensity) && light.intensity >= 0.0))
            return "light intensity not finite and >= 0";
    }

    if (scene.shaderNames.size() != scene.shaders.size())
        return "shader names and shaders differ in count";
    if (std::set<std::string>(scene.shaderNames.begin(), scene.shaderNames.end()).size() != scene.shaderNames.size()) {
        return "duplicate shader name";
    }
    for (const Shader& shader : scene.shaders) {
        if (shader.valueless_by_exception())
            return "shader variant empty";
        if (const auto* s = std::get_if<ConstantShader>(&shader); s && !validColour(s->color))
            return "constant colour";
        if (const auto* s = std::get_if<LambertShader>(&shader); s && !validColour(s->color))
            return "lambert colour";
        if (const auto* s = std::get_if<CheckerShader>(&shader)) {
            if (!validColour(s->color1) || !validColour(s->color2))
                return "checker colour invalid";
            if (!(std::isfinite(s->size) && s->size > 0.0))
                return "checker size not finite and > 0";
            if (!supportedLength(s->size))
                return "checker size outside the supported range";
        }
    }

    for (const Node& node : scene.nodes) {
        if (node.geometry.valueless_by_exception())
            return "geometry variant empty";
        if (const auto* plane = std::get_if<Plane>(&node.geometry); plane && !std::isfinite(plane->height)) {
            return "plane height not finite";
        }
        if (const auto* plane = std::get_if<Plane>(&node.geometry); plane && !supportedLength(plane->height)) {
            return "plane height outside the supported range";
        }
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            if (!finite(sphere->center))
                return "sphere centre not finite";
            if (!(std::isfinite(sphere->radius) && sphere->radius > 0.0))
                return "sphere radius not finite and > 0";
            if (!supportedPoint(sphere->center) || !supportedLength(sphere->radius)) {
                return "sphere outside the supported range";
            }
        }
        if (node.shaderIndex >= scene.shaders.size())
            return "node shader index out of range";
    }
    return std::nullopt;
}

// Whether a rejection message has the promised shape: "SOURCE:LINE:COLUMN: JSON syntax error: ...",
// "SOURCE: PATH: REASON", PATH being (root) or a JSON path such as nodes[3].geometry.radius, or,
// for text in another encoding than UTF-8, "SOURCE: the file is ENCODING text, ...".
inline bool rejectionNamesPlace(const std::string& message, const std::string& source) {
    if (message.rfind(source + ":", 0) != 0)
        return false;
    const std::string rest = message.substr(source.size() + 1);
    const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    const auto hasReasonAfter = [&](std::size_t at) { return at < rest.size() && rest[at] != ' '; };
    const std::string kEncoding = " the file is UTF-";
    if (rest.compare(0, kEncoding.size(), kEncoding) == 0)
        return hasReasonAfter(kEncoding.size());
    // LINE:COLUMN
    std::size_t i = 0;
    while (i < rest.size() && isDigit(rest[i]))
        ++i;
    if (i > 0) {
        if (i >= rest.size() || rest[i] != ':')
            return false;
        const std::size_t columnStart = ++i;
        while (i < rest.size() && isDigit(rest[i]))
            ++i;
        const std::string kSyntax = ": JSON syntax error: ";
        return i > columnStart && rest.compare(i, kSyntax.size(), kSyntax) == 0 && hasReasonAfter(i + kSyntax.size());
    }
    // PATH: (root), or a key followed by .key, [index] and ["any key"] (a JSON string, maybe cut
    // short with ...), as scene/json_path.h writes them; a quoted key may itself hold ": ".
    if (rest.size() < 2 || rest[0] != ' ')
        return false;
    std::size_t at = 1;
    if (rest.compare(at, 6, "(root)") == 0) {
        at += 6;
    } else {
        const auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
        const auto skipIdentifier = [&] {
            const std::size_t start = at;
            while (at < rest.size() && (isLetter(rest[at]) || (at > start && isDigit(rest[at]))))
                ++at;
            return at > start;
        };
        const auto skipBracket = [&] {  // at the '['
            ++at;
            if (at < rest.size() && rest[at] == '"') {
                for (++at; at < rest.size() && rest[at] != '"'; ++at) {
                    if (rest[at] == '\\')
                        ++at;
                }
                if (at >= rest.size())
                    return false;
                ++at;
                if (rest.compare(at, 3, "...") == 0)
                    at += 3;
            } else {
                const std::size_t start = at;
                while (at < rest.size() && isDigit(rest[at]))
                    ++at;
                if (at == start)
                    return false;
            }
            return at < rest.size() && rest[at++] == ']';
        };
        if (!(rest[at] == '[' ? skipBracket() : skipIdentifier()))
            return false;
        while (at < rest.size() && (rest[at] == '[' || rest[at] == '.')) {
            if (!(rest[at] == '[' ? skipBracket() : (++at, skipIdentifier())))
                return false;
        }
    }
    return rest.compare(at, 2, ": ") == 0 && hasReasonAfter(at + 2);
}

}  // namespace hexray::test
