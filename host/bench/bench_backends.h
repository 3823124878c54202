#pragma once
// What `hexray bench` measures: each backend it can time, rendering one scene once per call, and
// what a render is timed and judged by. The renderers themselves are the project's own; the
// bench's yardsticks (the hand-written kernel, Embree) live beside it.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/gpu_renderer.h"
#include "gpu/render_plan.h"
#include "gpu/tile_classes.h"
#include "image/image.h"
#include "image/image_io.h"
#include "image/pixel_class.h"
#include "scene/scene.h"
#include "util/milliseconds_since.h"
#include "vulkan/vulkan_context.h"

namespace hexray::inline embree {
class EmbreeRenderer;        // embree/embree_renderer.h
class EmbreePacketRenderer;  // embree/embree_packet_renderer.h
}  // namespace hexray::embree

namespace hexray::inline bench {

enum class BenchBackend {
    Gpu,               // the renderer, as planRender decides for a precision and culling
    GpuHandWritten,    // the lecture demo's hand-written kernel (bench/lecture_demo_ceiling.h)
    Cpu,               // the CPU reference
    Embree,            // Embree 3 at its best: the widest native packets, shading in float (EmbreePacketRenderer)
    EmbreeF64Packets,  // Embree 3, 8-ray packets, shading in double through the CPU reference's code
    EmbreeF64Single,   // Embree 3, one ray at a time, shading in double as above
};

// The GPU kernel a configuration ran: the plan decides, whatever the configuration asked (culling
// applies to generated kernels only).
enum class BenchKernel {
    None,                  // not a GPU backend
    Generated,             // generated for the scene (uniform layout)
    DataDriven,            // the data-driven kernel, every node for every ray
    DataDrivenCandidates,  // the data-driven kernel with candidate lists
    HandWritten,           // the lecture demo's hand-written kernel
};

// "generated", "data-driven", "data-driven-candidates", "hand-written"; "" for None.
const char* benchKernelName(BenchKernel kernel);

// One thing to measure: a backend (with a precision and culling for the GPU) at a sample count on
// one scene.
struct BenchConfiguration {
    std::size_t scene = 0;  // into the bench's scene list
    BenchBackend backend = BenchBackend::Gpu;
    Precision precision = Precision::Auto;
    Culling culling = Culling::Off;
    std::uint32_t samplesPerPixel = 1;
};

// Every render of one configuration.
struct BenchMeasurement {
    std::vector<double> renderMilliseconds;  // the backend's own timing of the render (see the report)
    std::vector<double> frameMilliseconds;   // the whole frame in-process: planning, upload, render
    std::vector<double> planMilliseconds;    // GPU: planning (structures it builds on the host: candidate lists)
    std::vector<double> uploadMilliseconds;  // GPU: packing and uploading the scene
    Image image;                             // CPU reference and Embree: linear
    Rgb8Image encoded;                       // GPU: the 8-bit output `render` writes
    std::vector<PixelClass> classes;         // empty for the hand-written kernel, which writes none
    std::vector<float> margins;              // CPU reference only
    Precision precision = Precision::Auto;   // GPU: the plan's
    BenchKernel kernel = BenchKernel::None;  // GPU: the kernel the plan chose
    bool culled = false;                     // GPU: rendered by tile classes (culling applied)
    CertifiedFallback fallback;              // GPU f32-certified: the last round's pixels rendered again in f64
};

class BenchBackends {
public:
    BenchBackends(const VulkanContext::Options& vulkan);
    ~BenchBackends();

    bool hasFloat64() const { return context_.selected().hasFloat64; }
    bool hasEmbree() const { return embree_ != nullptr; }
    const DeviceInfo& device() const { return context_.selected(); }
    // Milliseconds to create the Vulkan context (instance and device).
    double startupMilliseconds() const { return startupMilliseconds_; }
    std::string embreeVersion() const;
    Precision autoPrecision(const Scene& scene) const { return gpu_.resolve(scene, Precision::Auto); }
    // The GPU renderer's pipelines made so far (GpuRenderer::pipelinesCreated).
    std::uint64_t gpuPipelinesCreated() const { return gpu_.pipelinesCreated(); }

    // "lavapipe", "lavapipe hand-written", "cpu-reference", "embree 8-ray packets (f32 shading)" (the
    // packet width this CPU runs), "embree 8-ray packets (f64 shading)", "embree single rays (f64 shading)".
    std::string name(BenchBackend backend) const;
    // The threads the backend renders with, for the per-pixel cost; 0 for a real GPU.
    unsigned threads(BenchBackend backend) const;

    // Renders once into `measurement`, appending its times. `withClasses`: the GPU also renders,
    // untimed, the pixel classes its 8-bit output does not carry.
    void measure(const Scene& scene, const BenchConfiguration& configuration, bool withClasses,
                 BenchMeasurement& measurement);

    // The tests a GPU configuration's kernel runs per pixel; nothing for a data-driven kernel or
    // another backend.
    std::optional<WorkPerPixel> work(const Scene& scene, const BenchConfiguration& configuration) const;

private:
    void measureGpu(const Scene& scene, const BenchConfiguration& configuration, bool withClasses,
                    BenchMeasurement& measurement);
    void measureEmbree(const Scene& scene, BenchBackend backend, BenchMeasurement& measurement);

    std::chrono::steady_clock::time_point constructed_ = std::chrono::steady_clock::now();  // before context_
    VulkanContext context_;
    double startupMilliseconds_ = millisecondsSince(constructed_);  // after context_
    GpuRenderer gpu_;
    bool isLavapipe_ = false;
    std::string gpuName_;
    // Complete only where Embree is built in, so its deleter is defined there (bench_backends.cpp).
    struct EmbreeDeleter {
        void operator()(EmbreeRenderer* renderer) const;
        void operator()(EmbreePacketRenderer* renderer) const;
    };
    std::unique_ptr<EmbreeRenderer, EmbreeDeleter> embree_;                 // null without Embree
    std::unique_ptr<EmbreePacketRenderer, EmbreeDeleter> embreeAtItsBest_;  // null without Embree
};

}  // namespace hexray::bench
