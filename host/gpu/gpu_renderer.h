#pragma once
// Renders a scene with the compute shader in shaders/render.comp.

#include "image/image.h"
#include "scene/scene.h"
#include "vulkan/vulkan_context.h"

namespace hexray {

struct GpuTiming {
    double renderMilliseconds = 0;         // all bands, measured after the warm-up dispatch
    double firstDispatchMilliseconds = 0;  // the warm-up: includes the driver's shader compile
    bool fromTimestamps = false;           // false: host wall time (no timestamp support)
};

struct GpuRenderResult {
    Image image;
    GpuTiming timing;
};

// Owns the pipeline for one device; render() may be called for any number of scenes.
class GpuRenderer {
public:
    // Images whose pixels exceed `maxBandBytes` (or the device's storage-buffer limit, if
    // smaller) render in several bands of rows.
    static constexpr std::uint64_t kDefaultMaxBandBytes = std::uint64_t{256} << 20;

    explicit GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes = kDefaultMaxBandBytes);

    GpuRenderResult render(const Scene& scene);

private:
    const VulkanContext& context_;
    std::uint64_t maxBandBytes_;
    vk::raii::DescriptorSetLayout setLayout_;
    vk::raii::PipelineLayout pipelineLayout_;
    vk::raii::Pipeline pipeline_;
    vk::raii::CommandPool commandPool_;
    vk::raii::QueryPool timestamps_;  // null when the queue cannot write timestamps
    double nanosecondsPerTick_ = 1.0;
    std::uint64_t timestampMask_ = ~std::uint64_t{0};
};

}  // namespace hexray
