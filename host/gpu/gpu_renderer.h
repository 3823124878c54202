#pragma once
// Renders a scene with the compute shader in shaders/render.comp.

#include <functional>
#include <map>
#include <span>
#include <tuple>
#include <vector>

#include "accel/bvh.h"
#include "gpu/gpu_layout.h"
#include "gpu/gpu_scene.h"
#include "gpu/precision.h"
#include "image/image.h"
#include "image/image_io.h"
#include "image/pixel_class.h"
#include "scene/scene.h"
#include "vulkan/vulkan_context.h"

namespace hexray {

struct GpuTiming {
    double renderMilliseconds = 0;         // all bands, measured after the warm-up dispatch
    double firstDispatchMilliseconds = 0;  // the warm-up: includes the driver's shader compile
    bool fromTimestamps = false;           // false: host wall time (no timestamp support)
};

// What render() produces: linear RGB and what each pixel shows, for comparisons; or only the
// finished 8-bit image, encoded on the device as the scene asks (sRGB or linear).
enum class GpuOutput { LinearAndClasses, Encoded8 };

struct GpuRenderResult {
    Image image;                      // LinearAndClasses
    std::vector<PixelClass> classes;  // LinearAndClasses: per pixel, row-major like the image
    Rgb8Image encoded;                // Encoded8
    Precision precision = Precision::F32;  // the variant that rendered (never Auto)
    GpuTiming timing;
    bool usedBvh = false;  // the spheres were traced through a BVH
};

// Owns the pipelines for one device: one per precision variant and scene specialization,
// each built on first use. render() may be called for any number of scenes.
class GpuRenderer {
public:
    // Images whose pixels exceed `maxBandBytes` (or the device's storage-buffer limit, if
    // smaller) render in several bands of rows.
    static constexpr std::uint64_t kDefaultMaxBandBytes = std::uint64_t{256} << 20;

    explicit GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes = kDefaultMaxBandBytes);

    // Precision::Auto picks per scene (choosePrecision). Throws VulkanError for F64 on a
    // device without shaderFloat64.
    // Acceleration::Auto traces scenes too large for the uniform-buffer layout through a BVH
    // when bvhPays(scene); every choice gives the same image.
    GpuRenderResult render(const Scene& scene, Precision precision = Precision::Auto,
                           GpuOutput output = GpuOutput::LinearAndClasses,
                           Acceleration acceleration = Acceleration::Auto);

    // The 8-bit image a band of rows at a time, each handed to `consume` (first row, and the
    // rows' RGB bytes) as soon as it is read back: the whole image is never in memory.
    using RowConsumer = std::function<void(std::uint32_t firstRow, std::span<const std::uint8_t> rgbRows)>;
    GpuRenderResult renderEncodedRows(const Scene& scene, Precision precision, const RowConsumer& consume);

    // The precision render() would use for `scene`.
    Precision resolve(const Scene& scene, Precision requested) const;

private:
    // One band of rows as the device left it; only the output's own buffer is meaningful.
    struct Band {
        std::uint32_t firstRow;
        std::uint32_t rows;
        const gpu::GpuPixel* pixels;
        const gpu::GpuPixelClass* classes;
        const gpu::GpuEncodedPixel* encoded;
    };
    // Sets `result`'s timing and usedBvh.
    void renderBands(const Scene& scene, Precision precision, GpuOutput output, Acceleration acceleration,
                     GpuRenderResult& result, const std::function<void(const Band&)>& consume);

    // The descriptor set layout and pipeline layout for one way of uploading the scene.
    struct SceneBindings {
        vk::raii::DescriptorSetLayout setLayout;
        vk::raii::PipelineLayout pipelineLayout;
    };
    using PipelineKey = std::tuple<Precision, gpu::SceneLayout, gpu::ShaderSpecialization>;

    const SceneBindings& bindings(gpu::SceneLayout layout) const {
        return layout == gpu::SceneLayout::Uniform ? uniformScene_ : storageScene_;
    }
    const vk::raii::Pipeline& pipeline(const PipelineKey& key);

    const VulkanContext& context_;
    std::uint64_t maxBandBytes_;
    SceneBindings uniformScene_;  // small scenes: scene data in uniform buffers
    SceneBindings storageScene_;  // larger ones: in storage buffers, with or without a BVH
    std::map<PipelineKey, vk::raii::Pipeline> pipelines_;
    vk::raii::CommandPool commandPool_;
    vk::raii::QueryPool timestamps_;  // null when the queue cannot write timestamps
    double nanosecondsPerTick_ = 1.0;
    std::uint64_t timestampMask_ = ~std::uint64_t{0};
};

}  // namespace hexray
