#pragma once
// Renders a scene with a compute kernel, as a RenderPlan (render_plan.h) says: a kernel
// generated for the scene, or the data-driven shaders/render.comp.

#include <functional>
#include <span>
#include <tuple>
#include <vector>

#include "accel/bvh.h"
#include "layout/gpu_layout.h"
#include "kernels/kernel_compiler.h"
#include "precision/precision.h"
#include "gpu/pixel_trace.h"
#include "gpu/render_plan.h"
#include "image/image.h"
#include "image/image_io.h"
#include "image/pixel_class.h"
#include "image/row_range.h"
#include "scene/scene.h"
#include "util/lru_map.h"
#include "vulkan/vulkan_context.h"

namespace hexray::inline gpu {

// f32-certified: the pixels a decision of which was in doubt, rendered again in f64.
struct CertifiedFallback {
    std::uint64_t pixels = 0;        // rendered again
    std::uint64_t totalPixels = 0;   // rendered
    std::uint64_t vectors = 0;       // 8-pixel rows of a tile (a lavapipe vector) with a pixel in doubt
    std::uint64_t totalVectors = 0;  // 8-pixel rows of a tile rendered
};

struct GpuTiming {
    double renderMilliseconds = 0;         // all bands, measured after the warm-up dispatch
    double firstDispatchMilliseconds = 0;  // the warm-up: includes the driver's compile (lavapipe's JIT)
    bool fromTimestamps = false;           // false: host wall time (no timestamp support)
    double uploadMilliseconds = 0;         // packing the scene and uploading it (and its candidate lists) to the device
    KernelBuild kernel;                    // generating and compiling the kernel (when not yet built)
    CertifiedFallback fallback;            // f32-certified only
};

// What render() produces: linear RGB and what each pixel shows, for comparisons; or only the
// finished 8-bit image, encoded on the device as the scene asks (sRGB or linear).
// LinearClassesAndAov adds, from each pixel's first sample, the hit distance and the shading
// normal (for `render --aov`).
enum class GpuOutput { LinearAndClasses, Encoded8, LinearClassesAndAov };

struct GpuRenderResult {
    Image image;                      // LinearAndClasses
    std::vector<PixelClass> classes;  // LinearAndClasses: per pixel, row-major like the image
    Rgb8Image encoded;                // Encoded8
    // LinearClassesAndAov, per pixel from its first sample: the hit distance in world units
    // (+inf for the background) and the shading normal (0 for the background).
    std::vector<float> depth;
    std::vector<glm::vec3> normals;
    Precision precision = Precision::F32;  // the plan's (never Auto)
    GpuTiming timing;
    bool usedCandidateLists = false;  // the spheres were found through candidate lists
};

// One band of rows as the device left it (in mapped memory); only the output's own buffer is
// meaningful. GpuRenderer's own: what it hands from the dispatch to the read-back.
struct RenderedBand {
    std::uint32_t firstRow;
    std::uint32_t rows;
    gpu::GpuPixel* pixels;
    gpu::GpuPixelClass* classes;
    gpu::GpuEncodedPixel* encoded;
    gpu::GpuAovPixel* aovs;
    const std::byte* trace;
};

// Owns the pipelines for one device, each built on first use, and the kernel compiler; keeps the
// most recently used of both (kept_kernels.h). render() may be called for any number of scenes and
// plans.
class GpuRenderer {
public:
    // Images whose pixels exceed `maxBandBytes` (or the device's storage-buffer limit, if
    // smaller) render in several bands of rows.
    static constexpr std::uint64_t kDefaultMaxBandBytes = std::uint64_t{256} << 20;

    explicit GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes = kDefaultMaxBandBytes,
                         KernelCache kernelCache = KernelCache(KernelCache::defaultDirectory()), KeptKernels kept = {});
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // The plan for `scene` on this device (planRender). Throws PlanRefused where the device
    // cannot render it as asked.
    RenderPlan plan(const Scene& scene, const PlanRequest& request = {}) const;

    GpuRenderResult render(const Scene& scene, const RenderPlan& plan, GpuOutput output);

    // The 8-bit image a band of rows at a time, each handed to `consume` (first row, and the
    // rows' RGB bytes) as soon as it is read back: the whole image is never in memory. Only the
    // rows in `rows`, each exactly as in the whole image.
    using RowConsumer = std::function<void(std::uint32_t firstRow, std::span<const std::uint8_t> rgbRows)>;
    GpuRenderResult renderEncodedRows(const Scene& scene, const RenderPlan& plan, const RowConsumer& consume,
                                      RowRange rows = {});

    // render()'s LinearAndClasses or LinearClassesAndAov output a band of rows at a time: each
    // band is handed to `consume` (its first row, and a result whose image, classes, depth and
    // normals hold just the band's rows) as soon as it is read back. The returned result has the
    // precision, timing and usedCandidateLists, and no pixels.
    using BandConsumer = std::function<void(std::uint32_t firstRow, const GpuRenderResult& band)>;
    GpuRenderResult renderLinearRows(const Scene& scene, const RenderPlan& plan, GpuOutput output,
                                     const BandConsumer& consume, RowRange rows = {});

    // Replays pixel (x, y) in the kernel's trace mode and returns what it computed for sample
    // `sample` (and the pixel's colour). The caller checks the ranges.
    GpuPixelTrace tracePixel(const Scene& scene, const RenderPlan& plan, std::uint32_t x, std::uint32_t y,
                             std::uint32_t sample);

    // Shorthands that plan first.
    GpuRenderResult render(const Scene& scene, Precision precision = Precision::Auto,
                           GpuOutput output = GpuOutput::LinearAndClasses,
                           Acceleration acceleration = Acceleration::Auto) {
        return render(scene, plan(scene, {precision, acceleration}), output);
    }
    GpuPixelTrace tracePixel(const Scene& scene, Precision precision, std::uint32_t x, std::uint32_t y,
                             std::uint32_t sample) {
        return tracePixel(scene, plan(scene, {precision}), x, y, sample);
    }

    // The precision a plan for `scene` would use (without building the rest of the plan).
    Precision resolve(const Scene& scene, Precision requested) const;

    // Drops the generated kernels and their pipelines, each made for one scene's structure and
    // values; the data-driven kernels' pipelines stay. (Memory is bounded without it: kept_kernels.h.)
    void releaseGeneratedKernels();

    DeviceAbilities abilities() const;

    // How many pipelines, and generated kernels' SPIR-V, are held now.
    std::size_t keptPipelines() const { return pipelines_.size(); }
    // Pipelines made so far (kept or since dropped): a kernel made again after eviction counts again.
    std::uint64_t pipelinesCreated() const { return pipelinesCreated_; }
    std::size_t keptGeneratedKernels() const { return kernels_.keptKernels(); }

private:
    using Band = RenderedBand;
    // Renders the rows in `rowRange`. Sets `result`'s precision, timing and usedCandidateLists.
    // With `traceRequest` non-empty, one trace dispatch instead (see tracePixel): the trace buffer
    // starts as those bytes.
    void renderBands(const Scene& scene, const RenderPlan& plan, GpuOutput output, GpuRenderResult& result,
                     const std::function<void(const Band&)>& consume, RowRange rowRange,
                     std::span<const std::byte> traceRequest = {});

    // f32-certified: renders again, with `fallback` (the f64 plan for listed pixels), each pixel of
    // the band whose alpha the certified kernel set to 0, and writes it into the band's buffers.
    void renderPixelsInDoubt(const Scene& scene, const RenderPlan& fallback, GpuOutput output, const Band& band,
                             GpuRenderResult& result);

    // The descriptor set layout and pipeline layout for one way of uploading the scene.
    struct SceneBindings {
        vk::raii::DescriptorSetLayout setLayout;
        vk::raii::PipelineLayout pipelineLayout;
    };
    const SceneBindings& bindings(SceneLayout layout) const {
        return layout == SceneLayout::Uniform ? uniformScene_ : texelScene_;
    }
    // Pipelines by kernel (a prebuilt one's SPIR-V address, or a generated one's
    // KernelBuild::generatedId), layout and specialization (a generated kernel's scene values
    // included).
    using PipelineKey =
        std::tuple<const std::uint32_t*, std::uint64_t, bool, gpu::Specialization, std::vector<std::byte>>;
    const vk::raii::Pipeline& pipeline(std::span<const std::uint32_t> spirv, std::uint64_t generatedId,
                                       SceneLayout layout, const gpu::Specialization& specialization,
                                       std::span<const std::byte> sceneValues,
                                       std::span<const std::uint32_t> sceneSizes);
    // The pipelines of `kernels` for `plan`, their build times added to `timing`.
    std::vector<const vk::raii::Pipeline*> pipelinesFor(std::span<const Kernel> kernels, const RenderPlan& plan,
                                                        const gpu::Specialization& specialization,
                                                        std::span<const std::byte> sceneValues,
                                                        std::span<const std::uint32_t> sceneSizes, KernelBuild& timing);
    // `kernel`'s SPIR-V (see KernelCompiler) and its pipeline. SPIR-V from the disk cache that the
    // driver refuses is a miss: it is compiled afresh and the pipeline made again; only a failure on
    // fresh SPIR-V is an error.
    const vk::raii::Pipeline& kernelPipeline(const Kernel& kernel, KernelBuild& build, SceneLayout layout,
                                             const gpu::Specialization& specialization,
                                             std::span<const std::byte> sceneValues,
                                             std::span<const std::uint32_t> sceneSizes);

    const VulkanContext& context_;
    std::uint64_t maxBandBytes_;
    KernelCompiler kernels_;
    SceneBindings uniformScene_;  // small scenes: scene data in uniform buffers
    SceneBindings texelScene_;    // larger ones: in texel buffers, with or without candidate lists
    LruMap<PipelineKey, vk::raii::Pipeline> pipelines_;
    std::uint64_t pipelinesCreated_ = 0;
    vk::raii::CommandPool commandPool_;
    vk::raii::QueryPool timestamps_;  // null when the queue cannot write timestamps
    double nanosecondsPerTick_ = 1.0;
    std::uint64_t timestampMask_ = ~std::uint64_t{0};
};

}  // namespace hexray::gpu
