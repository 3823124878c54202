#include "cpu/cpu_explain.h"

#include <variant>

#include <glm/common.hpp>

#include "camera/camera.h"
#include "cpu/cpu_renderer.h"
#include "cpu/eye_frame.h"

namespace hexray::inline cpu {

CpuPixelExplanation explainPixel(const Scene& world, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    const EyeFrameScene frame = inEyeFrame(world);  // traced as renderOnCpu traces, reported in world units
    const Scene& scene = frame.scene;
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    CpuPixelExplanation out;
    out.pixelColor = Color(0.0);
    for (std::uint32_t s = 0; s < scene.image.samplesPerPixel; ++s) {
        const Ray ray = cameraRay(sheet, scene.image, x, y, s);
        const std::optional<SceneHit> nearest = findNearestHit(ray, scene);
        Color color = scene.background;
        if (nearest) {
            // The explained sample keeps every light's term; the shading is renderOnCpu's own.
            const Node& node = scene.nodes[nearest->nodeIndex];
            const ShadedHit shaded =
                shadeHit(scene, node, nearest->hit, nullptr, s == sample ? &out.lights : nullptr, frame.eye);
            color = shaded.color;
            if (s == sample) {
                const Shader& shader = scene.shaders.at(node.shaderIndex);
                out.constantShaded = std::holds_alternative<ConstantShader>(shader);
                out.albedo = shaded.albedo;
                if (shaded.checkerUv) {
                    out.uv = *shaded.checkerUv;
                    out.checkerCell = glm::floor(out.uv / std::get<CheckerShader>(shader).size);
                }
                out.pixelClass = PixelClass{std::uint32_t(nearest->nodeIndex), shaded.flags};
            }
        }
        out.pixelColor += color;
        if (s == sample) {
            out.ray = ray;
            out.nearest = nearest;
            out.sampleColor = color;
        }
    }
    out.pixelColor /= double(scene.image.samplesPerPixel);
    for (const Node& node : scene.nodes) {
        out.candidates.push_back(intersectGeometry(out.ray, node.geometry));
    }
    out.ray.origin += frame.eye;
    if (out.nearest) {
        out.nearest->hit.point += frame.eye;
    }
    return out;
}

}  // namespace hexray::cpu
