#include "bench/bench_backends.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "bench/lecture_demo_ceiling.h"
#include "cpu/cpu_renderer.h"
#include "util/milliseconds_since.h"
#ifdef HEXRAY_WITH_EMBREE
#include "embree/embree_packet_renderer.h"
#include "embree/embree_renderer.h"
#endif

namespace hexray::inline bench {
namespace {

// The threads lavapipe renders with: Mesa's own override, else one per core.
unsigned lavapipeThreads() {
    if (const char* value = std::getenv("LP_NUM_THREADS")) {
        return unsigned(std::max(1L, std::strtol(value, nullptr, 10)));
    }
    return cpuThreadCount(0);
}

// A round measures every configuration in turn, and culling alone needs a kernel per tile class
// in each precision: with the renderer's default bounds (kept_kernels.h) each frame would find
// its kernels evicted by the previous configuration's and rebuild them from the disk cache, and
// "frame ms" would measure that. The bench keeps them all.
constexpr KeptKernels kBenchKeptKernels{64, 64};

BenchKernel kernelOf(const RenderPlan& plan, bool handWritten) {
    if (handWritten) {
        return BenchKernel::HandWritten;
    }
    switch (plan.layout) {
        case SceneLayout::Uniform:
            return BenchKernel::Generated;
        case SceneLayout::Texels:
            return BenchKernel::DataDriven;
        case SceneLayout::TexelsCandidates:
            return BenchKernel::DataDrivenCandidates;
    }
    return BenchKernel::None;
}

}  // namespace

const char* benchKernelName(BenchKernel kernel) {
    switch (kernel) {
        case BenchKernel::None:
            return "";
        case BenchKernel::Generated:
            return "generated";
        case BenchKernel::DataDriven:
            return "data-driven";
        case BenchKernel::DataDrivenCandidates:
            return "data-driven-candidates";
        case BenchKernel::HandWritten:
            return "hand-written";
    }
    return "";
}

#ifdef HEXRAY_WITH_EMBREE
BenchBackends::BenchBackends(const VulkanContext::Options& vulkan)
    : context_(vulkan),
      gpu_(context_, GpuRenderer::kDefaultMaxBandBytes, KernelCache(KernelCache::defaultDirectory()),
           kBenchKeptKernels),
      embree_(new EmbreeRenderer(cpuThreadCount(0))),
      embreeAtItsBest_(new EmbreePacketRenderer(cpuThreadCount(0))) {
#else
BenchBackends::BenchBackends(const VulkanContext::Options& vulkan)
    : context_(vulkan),
      gpu_(context_, GpuRenderer::kDefaultMaxBandBytes, KernelCache(KernelCache::defaultDirectory()),
           kBenchKeptKernels) {
#endif
    isLavapipe_ = context_.selected().name.find("llvmpipe") != std::string::npos;
    gpuName_ = isLavapipe_ ? "lavapipe" : context_.selected().name;
}

BenchBackends::~BenchBackends() = default;

void BenchBackends::EmbreeDeleter::operator()([[maybe_unused]] EmbreeRenderer* renderer) const {
#ifdef HEXRAY_WITH_EMBREE
    delete renderer;
#endif
}

void BenchBackends::EmbreeDeleter::operator()([[maybe_unused]] EmbreePacketRenderer* renderer) const {
#ifdef HEXRAY_WITH_EMBREE
    delete renderer;
#endif
}

std::string BenchBackends::embreeVersion() const {
#ifdef HEXRAY_WITH_EMBREE
    return embree_->version();
#else
    return "";
#endif
}

std::string BenchBackends::name(BenchBackend backend) const {
    switch (backend) {
        case BenchBackend::Gpu:
            return gpuName_;
        case BenchBackend::GpuHandWritten:
            return gpuName_ + " hand-written";
        case BenchBackend::Cpu:
            return "cpu-reference";
        case BenchBackend::Embree:
#ifdef HEXRAY_WITH_EMBREE
            return "embree " + std::to_string(embreeAtItsBest_->packetWidth()) + "-ray packets (f32 shading)";
#else
            return "embree";
#endif
        case BenchBackend::EmbreeF64Packets:
            return "embree 8-ray packets (f64 shading)";
        case BenchBackend::EmbreeF64Single:
            return "embree single rays (f64 shading)";
    }
    return "";
}

unsigned BenchBackends::threads(BenchBackend backend) const {
    switch (backend) {
        case BenchBackend::Gpu:
        case BenchBackend::GpuHandWritten:
            return isLavapipe_ ? lavapipeThreads() : 0;
        case BenchBackend::Cpu:
        case BenchBackend::Embree:
        case BenchBackend::EmbreeF64Packets:
        case BenchBackend::EmbreeF64Single:
            return cpuThreadCount(0);
    }
    return 0;
}

void BenchBackends::measureGpu(const Scene& scene, const BenchConfiguration& configuration, bool withClasses,
                               BenchMeasurement& measurement) {
    const auto start = std::chrono::steady_clock::now();
    const bool handWritten = configuration.backend == BenchBackend::GpuHandWritten;
    const RenderPlan plan =
        handWritten ? lectureDemoCeilingPlan(gpu_, scene)
                    : gpu_.plan(scene, {configuration.precision, Acceleration::Auto, configuration.culling});
    measurement.planMilliseconds.push_back(millisecondsSince(start));
    GpuRenderResult render = gpu_.render(scene, plan, GpuOutput::Encoded8);
    measurement.renderMilliseconds.push_back(render.timing.renderMilliseconds);
    measurement.frameMilliseconds.push_back(millisecondsSince(start));
    measurement.uploadMilliseconds.push_back(render.timing.uploadMilliseconds);
    measurement.encoded = std::move(render.encoded);
    measurement.precision = plan.precision;
    measurement.kernel = kernelOf(plan, handWritten);
    measurement.culled = plan.tileClasses.classification != nullptr;
    measurement.fallback = render.timing.fallback;
    if (withClasses && !handWritten) {
        measurement.classes = gpu_.render(scene, plan, GpuOutput::LinearAndClasses).classes;
    }
}

void BenchBackends::measure(const Scene& scene, const BenchConfiguration& configuration, bool withClasses,
                            BenchMeasurement& measurement) {
    const auto start = std::chrono::steady_clock::now();
    switch (configuration.backend) {
        case BenchBackend::Gpu:
        case BenchBackend::GpuHandWritten:
            measureGpu(scene, configuration, withClasses, measurement);
            return;
        case BenchBackend::Cpu: {
            CpuRender render = renderOnCpu(scene);
            measurement.renderMilliseconds.push_back(millisecondsSince(start));
            measurement.frameMilliseconds.push_back(measurement.renderMilliseconds.back());
            measurement.image = std::move(render.image);
            measurement.classes = std::move(render.classes);
            measurement.margins = std::move(render.margins);
            return;
        }
        case BenchBackend::Embree:
        case BenchBackend::EmbreeF64Packets:
        case BenchBackend::EmbreeF64Single:
            measureEmbree(scene, configuration.backend, measurement);
            return;
    }
}

void BenchBackends::measureEmbree([[maybe_unused]] const Scene& scene, [[maybe_unused]] BenchBackend backend,
                                  [[maybe_unused]] BenchMeasurement& measurement) {
#ifdef HEXRAY_WITH_EMBREE
    const auto start = std::chrono::steady_clock::now();
    EmbreeRender render = backend == BenchBackend::Embree ? embreeAtItsBest_->render(scene)
                          : backend == BenchBackend::EmbreeF64Packets
                              ? embree_->render(scene, EmbreeTracing::Packets)
                              : embree_->render(scene, EmbreeTracing::SingleRays);
    measurement.renderMilliseconds.push_back(render.renderMilliseconds);
    measurement.frameMilliseconds.push_back(millisecondsSince(start));
    measurement.image = std::move(render.image);
    measurement.classes = std::move(render.classes);
#endif
}

std::optional<WorkPerPixel> BenchBackends::work(const Scene& scene, const BenchConfiguration& configuration) const {
    if (configuration.backend != BenchBackend::Gpu) {
        return std::nullopt;
    }
    const RenderPlan plan = gpu_.plan(scene, {configuration.precision, Acceleration::Auto, configuration.culling});
    if (!plan.kernel.code) {
        return std::nullopt;
    }
    if (plan.tileClasses.classification) {
        return workPerPixel(*plan.kernel.code, *plan.tileClasses.classification, scene.image);
    }
    return workPerPixel(*plan.kernel.code);
}

}  // namespace hexray::bench
