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
// LinearClassesAndAov adds, from each pixel's first sample, the hit distance and the shading
// normal (for `render --aov`).
enum class GpuOutput { LinearAndClasses, Encoded8, LinearClassesAndAov };

// One light at a traced sample, as the shader saw it.
struct GpuTraceLight {
    std::uint32_t status = gpu::kTraceLightNotEvaluated;  // gpu::TraceLightStatus
    double cosTheta = 0;
    double distanceSquared = 0;  // world units²
    double shadowLength = 0;     // world units
    glm::vec3 contribution{0};   // colour × intensity × cos θ / r²
};

// One pixel explained by the shader itself (OUTPUT_TRACE). Everything is converted back to
// world units: the camera-relative placement's eye is added back and lengths multiplied by its
// scale (see gpu_scene.h), in double, from the shader's f32 or f64 values.
struct GpuPixelTrace {
    Precision precision = Precision::F32;
    bool cameraRelative = true;
    double scale = 1.0;              // the placement's power of two (1 for f32-naive)
    glm::dvec3 rayOrigin{0};
    glm::dvec3 rayDirection{0};
    std::vector<double> candidates;  // per node: t in world units, +inf for a miss
    std::uint32_t node = PixelClass::kBackground;
    std::uint32_t flags = 0;         // as PixelClass::flags
    double t = 0;
    glm::dvec3 position{0};
    glm::dvec3 normal{0};            // shading normal
    glm::dvec3 shadowOrigin{0};
    glm::vec3 albedo{0};
    glm::vec3 sampleColor{0};        // the traced sample's linear colour
    glm::vec3 pixelColor{0};         // the pixel's (average of its samples)
    std::vector<GpuTraceLight> lights;
    bool usedBvh = false;  // the trace followed the BVH, as the scene's render does
};

struct GpuRenderResult {
    Image image;                      // LinearAndClasses
    std::vector<PixelClass> classes;  // LinearAndClasses: per pixel, row-major like the image
    Rgb8Image encoded;                // Encoded8
    // LinearClassesAndAov, per pixel from its first sample: the hit distance in world units
    // (+inf for the background) and the shading normal (0 for the background).
    std::vector<float> depth;
    std::vector<glm::vec3> normals;
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
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

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

    // render()'s LinearAndClasses or LinearClassesAndAov output a band of rows at a time: each
    // band is handed to `consume` (its first row, and a result whose image, classes, depth and
    // normals hold just the band's rows) as soon as it is read back. The returned result has the
    // precision, timing and usedBvh, and no pixels.
    using BandConsumer = std::function<void(std::uint32_t firstRow, const GpuRenderResult& band)>;
    GpuRenderResult renderLinearRows(const Scene& scene, Precision precision, GpuOutput output,
                                     const BandConsumer& consume, Acceleration acceleration = Acceleration::Auto);

    // Replays pixel (x, y) in the shader's trace mode and returns what it computed for sample
    // `sample` (and the pixel's colour). The caller checks the ranges.
    GpuPixelTrace tracePixel(const Scene& scene, Precision precision, std::uint32_t x, std::uint32_t y,
                             std::uint32_t sample);

    // The 8-bit image of the lecture demo scene from shaders/lecture_demo_ceiling.comp, a
    // hand-written kernel with the scene's values as literals: lavapipe's ceiling for that
    // scene, which `hexray bench` times beside render(). Throws std::invalid_argument unless
    // isLectureDemoScene(scene).
    GpuRenderResult renderLectureDemoCeiling(const Scene& scene);

    // The precision render() would use for `scene`.
    Precision resolve(const Scene& scene, Precision requested) const;

private:
    enum class Kernel { Renderer, LectureDemoCeiling };  // which compute shader runs
    GpuRenderResult renderEncoded(const Scene& scene, Precision precision, Kernel kernel);
    GpuRenderResult encodedRows(const Scene& scene, Precision precision, Kernel kernel, const RowConsumer& consume);

    // One band of rows as the device left it; only the output's own buffer is meaningful.
    struct Band {
        std::uint32_t firstRow;
        std::uint32_t rows;
        const gpu::GpuPixel* pixels;
        const gpu::GpuPixelClass* classes;
        const gpu::GpuEncodedPixel* encoded;
        const gpu::GpuAovPixel* aovs;
        const std::byte* trace;
    };
    // Sets `result`'s timing and usedBvh. With `traceRequest` non-empty, one trace dispatch
    // instead (see tracePixel): the trace buffer starts as those bytes.
    void renderBands(const Scene& scene, Precision precision, GpuOutput output, Acceleration acceleration,
                     Kernel kernel, GpuRenderResult& result, const std::function<void(const Band&)>& consume,
                     std::span<const std::byte> traceRequest = {});

    // The descriptor set layout and pipeline layout for one way of uploading the scene.
    struct SceneBindings {
        vk::raii::DescriptorSetLayout setLayout;
        vk::raii::PipelineLayout pipelineLayout;
    };
    using PipelineKey = std::tuple<Kernel, Precision, gpu::SceneLayout, gpu::ShaderSpecialization>;

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
