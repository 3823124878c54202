#include "cpu/cpu_renderer.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "cpu/cpu_intersect.h"
#include "cpu/cpu_shading.h"

namespace hexray {

namespace {

Ray cameraRay(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t x, std::uint32_t y) {
    const double offset = samplingOffset(image.sampling);
    const double sx = double(x) + offset;
    const double sy = double(y) + offset;
    const glm::dvec3 aim = sheet.topLeft + sheet.right * (sx / double(image.width)) +
                           sheet.down * (sy / double(image.height));
    // Camera rays start at t = 0 exactly: no offset, so nothing right in front of the eye is lost.
    return Ray{sheet.origin, glm::normalize(aim)};
}

Color traceRay(const Scene& scene, const Ray& ray) {
    const std::optional<SceneHit> nearest = findNearestHit(ray, scene);
    if (!nearest) {
        return scene.background;
    }
    return shadeHit(scene, scene.nodes[nearest->nodeIndex], nearest->hit);
}

void renderRow(const Scene& scene, const PixelSheet& sheet, std::uint32_t y, Image& image) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
        const Color color = traceRay(scene, cameraRay(sheet, scene.image, x, y));
        image.at(x, y) = glm::vec3(color);  // linear, not clamped: encoding happens later
    }
}

// A bad index would otherwise throw inside a worker thread, which ends the program.
void checkShaderIndices(const Scene& scene) {
    for (std::size_t index = 0; index < scene.nodes.size(); ++index) {
        if (scene.nodes[index].shaderIndex >= scene.shaders.size()) {
            throw std::out_of_range("renderOnCpu: nodes[" + std::to_string(index) +
                                    "] names shader " + std::to_string(scene.nodes[index].shaderIndex) +
                                    " but the scene has " + std::to_string(scene.shaders.size()));
        }
    }
}

}  // namespace

Image renderOnCpu(const Scene& scene, unsigned threadCount) {
    checkShaderIndices(scene);

    Image image(scene.image.width, scene.image.height);
    if (image.width == 0 || image.height == 0) {
        return image;
    }
    const PixelSheet sheet = makePixelSheet(scene.camera, sheetAspect(scene));

    if (threadCount == 0) {
        threadCount = std::max(1u, std::thread::hardware_concurrency());  // may report 0
    }
    threadCount = std::min(threadCount, image.height);

    // Rows are interleaved (worker w takes rows w, w + n, ...) so that expensive regions of
    // the image are shared out; each row is written by exactly one worker, so no locking.
    const auto renderRows = [&](unsigned worker) {
        for (std::uint32_t y = worker; y < image.height; y += threadCount) {
            renderRow(scene, sheet, y, image);
        }
    };
    {
        // jthread joins on destruction, also if starting a later worker throws.
        std::vector<std::jthread> workers;
        workers.reserve(threadCount - 1);
        for (unsigned worker = 1; worker < threadCount; ++worker) {
            workers.emplace_back(renderRows, worker);
        }
        renderRows(0);  // the calling thread is worker 0
    }
    return image;
}

}  // namespace hexray
