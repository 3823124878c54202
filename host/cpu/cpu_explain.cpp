#include "cpu/cpu_explain.h"

#include <cmath>
#include <limits>
#include <variant>

#include "accel/bvh.h"
#include "camera/camera.h"
#include "cpu/cpu_renderer.h"

namespace hexray {

CpuPixelExplanation explainPixel(const Scene& scene, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    CpuPixelExplanation out;
    out.pixelColor = Color(0.0);
    for (std::uint32_t s = 0; s < scene.image.samplesPerPixel; ++s) {
        const Ray ray = cameraRay(sheet, scene.image, x, y, s);
        const std::optional<SceneHit> nearest = findNearestHit(ray, scene);
        const Color color = nearest ? shadeHit(scene, scene.nodes[nearest->nodeIndex], nearest->hit) : scene.background;
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
    if (!out.nearest) {
        return out;
    }
    const Node& node = scene.nodes[out.nearest->nodeIndex];
    const Hit& hit = out.nearest->hit;
    const Shader& shader = scene.shaders.at(node.shaderIndex);
    out.pixelClass.node = std::uint32_t(out.nearest->nodeIndex);
    if (const auto* constant = std::get_if<ConstantShader>(&shader)) {
        out.constantShaded = true;
        out.albedo = constant->color;
        return out;
    }
    if (const auto* lambert = std::get_if<LambertShader>(&shader)) {
        out.albedo = lambert->color;
    } else {
        const CheckerShader& checker = std::get<CheckerShader>(shader);
        out.uv = textureCoordinates(node.geometry, hit);
        out.checkerCell = glm::floor(out.uv / checker.size);
        out.albedo = checkerColor(checker, out.uv);
        if (checkerParity(out.uv.x, out.uv.y, checker.size) == 1) {
            out.pixelClass.flags |= PixelClass::kOddCheckerBit;
        }
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& light = scene.lights[i];
        CpuLightExplanation explained{decideLight(scene, node.geometry, hit, light), Color(0.0)};
        if (explained.decision.reach == LightReach::Lit) {
            explained.contribution =
                light.color * (light.intensity * explained.decision.cosTheta / explained.decision.distanceSquared);
            out.pixelClass.flags |= PixelClass::litBit(std::uint32_t(i));
        }
        out.lights.push_back(explained);
    }
    return out;
}

CpuAovs renderCpuAovs(const Scene& scene) {
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));
    const std::optional<Bvh> bvh = bvhPays(scene) ? std::optional<Bvh>(buildBvh(scene)) : std::nullopt;
    const std::size_t count = std::size_t(scene.image.width) * scene.image.height;
    CpuAovs aovs{std::vector<float>(count, std::numeric_limits<float>::infinity()),
                 std::vector<glm::vec3>(count, glm::vec3(0.0f))};
    for (std::uint32_t y = 0; y < scene.image.height; ++y) {
        for (std::uint32_t x = 0; x < scene.image.width; ++x) {
            const Ray ray = cameraRay(sheet, scene.image, x, y, 0);
            if (const auto nearest = findNearestHit(ray, scene, bvh ? &*bvh : nullptr)) {
                const std::size_t index = std::size_t(y) * scene.image.width + x;
                aovs.depth[index] = float(nearest->hit.t);
                aovs.normals[index] = glm::vec3(nearest->hit.facingNormal);
            }
        }
    }
    return aovs;
}

}  // namespace hexray
