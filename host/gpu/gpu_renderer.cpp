#include "gpu/gpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "camera/camera.h"

#include "gpu/buffer_contents.h"
#include "gpu/candidate_buffers.h"
#include "gpu/plan_refused.h"
#include "layout/gpu_layout.h"
#include "gpu/gpu_scene.h"
#include "gpu/scene_constant_values.h"
#include "gpu/tile_classes.h"
#include "scene/scene_contents.h"
#include "util/milliseconds_since.h"
#include "util/out_of_memory.h"
#include "vulkan/fault_injection.h"
#include "vulkan/host_visible_buffer.h"

namespace hexray::inline gpu {
namespace {

using gpu::GpuBand;
using gpu::GpuPixel;
using gpu::GpuPixelClass;
using gpu::WORKGROUP_SIZE;

// The frame is a uniform buffer; a small scene's nodes and lights too, a larger scene's texel
// buffers (scene_data.glsl), as are the candidate lists; every other binding is a storage buffer.
vk::DescriptorType descriptorType(std::uint32_t binding, bool uniformScene) {
    if (binding == gpu::FRAME_BINDING) {
        return vk::DescriptorType::eUniformBuffer;
    }
    if (binding == gpu::NODE_BINDING || binding == gpu::LIGHT_BINDING) {
        return uniformScene ? vk::DescriptorType::eUniformBuffer : vk::DescriptorType::eUniformTexelBuffer;
    }
    if (CandidateBuffers::isCandidateBinding(binding)) {
        return vk::DescriptorType::eUniformTexelBuffer;
    }
    return vk::DescriptorType::eStorageBuffer;
}

vk::raii::DescriptorSetLayout createSetLayout(const vk::raii::Device& device, bool uniformScene) {
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding = 0; binding < gpu::BINDING_COUNT; ++binding) {
        bindings.emplace_back(binding, descriptorType(binding, uniformScene), 1, vk::ShaderStageFlagBits::eCompute);
    }
    return vk::raii::DescriptorSetLayout(device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

vk::raii::PipelineLayout createPipelineLayout(const vk::raii::Device& device,
                                              const vk::raii::DescriptorSetLayout& setLayout) {
    const vk::PushConstantRange band(vk::ShaderStageFlagBits::eCompute, 0, sizeof(GpuBand));
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    return vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo({}, layouts, band));
}

// The specialization constants: every kernel's (gpu::Specialization), then, for a generated kernel,
// the scene's values, one id per component (scene_constants.h), packed without padding.
struct SpecializationData {
    std::vector<std::byte> bytes;
    std::vector<vk::SpecializationMapEntry> entries;
};

SpecializationData specializationData(const gpu::Specialization& common, std::span<const std::byte> sceneValues,
                                      std::span<const std::uint32_t> sceneSizes) {
    SpecializationData data;
    const auto* raw = reinterpret_cast<const std::byte*>(&common);
    data.bytes.assign(raw, raw + sizeof common);
    for (std::uint32_t id = 0; id < gpu::FIRST_SCENE_CONSTANT_ID; ++id) {
        data.entries.emplace_back(id, id * sizeof(std::uint32_t), sizeof(std::uint32_t));
    }
    std::uint32_t offset = sizeof common;
    for (std::uint32_t i = 0; i < sceneSizes.size(); ++i) {
        data.entries.emplace_back(gpu::FIRST_SCENE_CONSTANT_ID + i, offset, sceneSizes[i]);
        offset += sceneSizes[i];
    }
    data.bytes.insert(data.bytes.end(), sceneValues.begin(), sceneValues.end());
    return data;
}

vk::raii::Pipeline createPipeline(const vk::raii::Device& device, const vk::raii::PipelineLayout& layout,
                                  std::span<const std::uint32_t> spirv, const SpecializationData& data) {
    if (injectedOnce(InjectedFault::PipelineFailsOnce)) {
        throw vk::UnknownError("vkCreateComputePipelines");
    }
    const vk::raii::ShaderModule module(device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
    const vk::SpecializationInfo specialization(data.entries, vk::ArrayProxyNoTemporaries<const std::byte>(data.bytes));
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main",
                                                  &specialization);
    return vk::raii::Pipeline(device, nullptr, vk::ComputePipelineCreateInfo({}, stage, *layout));
}

// The scene in the chosen variant's layout, as the bytes the buffers receive.
struct PackedScene {
    std::vector<std::byte> frame;
    BufferContents nodes;
    BufferContents lights;
    BufferContents candidateSpheres;  // empty: no candidate lists
    // A generated kernel's specialization constants: their values, and each component's size.
    std::vector<std::byte> constants;
    std::vector<std::uint32_t> constantSizes;
    bool valuesInBuffer = false;  // the kernel reads `constants` from a buffer instead

    // What the pipeline is specialised with, and what the buffer of values holds: one or the other.
    std::span<const std::byte> specValues() const {
        return valuesInBuffer ? std::span<const std::byte>() : std::span(constants);
    }
    std::span<const std::uint32_t> specSizes() const {
        return valuesInBuffer ? std::span<const std::uint32_t>() : std::span(constantSizes);
    }
    std::span<const std::byte> bufferedValues() const {
        return valuesInBuffer ? std::span(constants) : std::span<const std::byte>();
    }
};

template <typename T>
std::vector<std::byte> bytesOf(std::span<T> values) {
    const auto bytes = std::as_bytes(values);
    return {bytes.begin(), bytes.end()};
}

// The node buffer's contents: the nodes (packed already, or now straight into the buffer), then the looks.
template <typename Real>
BufferContents nodesThenLooks(const Scene& scene, const RenderPlan& plan, gpu::GpuScene<Real> packed,
                              bool packedInBuffer) {
    const std::size_t nodeBytes =
        (packedInBuffer ? scene.nodes.size() : packed.nodes.size()) * sizeof(gpu::GpuNode<Real>);
    const std::size_t lookBytes = packed.looks.size() * sizeof(gpu::GpuLook<Real>);
    auto held = std::make_shared<const gpu::GpuScene<Real>>(std::move(packed));
    return {nodeBytes + lookBytes, [&scene, &plan, held, packedInBuffer, nodeBytes, lookBytes](std::byte* out) {
                if (packedInBuffer) {
                    gpu::packNodesInto<Real>(scene, plan.placement, held->lookIndex, out);
                } else {
                    std::memcpy(out, held->nodes.data(), nodeBytes);
                }
                std::memcpy(out + nodeBytes, held->looks.data(), lookBytes);
            }};
}

template <typename Real>
PackedScene packBytes(const Scene& scene, const RenderPlan& plan) {
    // A large scene's nodes are packed straight into their buffer (a generated kernel's constants
    // read the packed nodes; its scenes are small).
    const bool packedInBuffer = !plan.kernel.code && plan.layout != SceneLayout::Uniform;
    gpu::GpuScene<Real> packed =
        gpu::packScene<Real>(scene, plan.placement, packedInBuffer ? NodePacking::Later : NodePacking::Now);
    PackedScene bytes;
    if (const CandidateLists* lists = plan.candidates.get()) {
        // The kernel finds the records' second array past every sphere's geometry (candidates.glsl).
        if (lists->sphereNodes.size() != packed.frame.nodeCount - packed.frame.planeCount) {
            throw std::logic_error("candidate lists: " + std::to_string(lists->sphereNodes.size()) +
                                   " sphere records for " +
                                   std::to_string(packed.frame.nodeCount - packed.frame.planeCount) + " spheres");
        }
        auto looks = std::make_shared<const gpu::LookIndex>(packed.lookIndex);
        bytes.candidateSpheres = {
            lists->sphereNodes.size() * gpu::kCandidateSphereBytes<Real>, [&scene, &plan, looks](std::byte* out) {
                gpu::packCandidateSpheresInto<Real>(scene, plan.placement, plan.candidates->sphereNodes, *looks, out);
            }};
    }
    if (plan.layout == SceneLayout::Uniform) {
        // A uniform block declares all SMALL_SCENE_CAPACITY entries: the buffers must hold them.
        packed.nodes.resize(gpu::SMALL_SCENE_CAPACITY);
        packed.looks.resize(gpu::SMALL_SCENE_CAPACITY);
        packed.lights.resize(gpu::SMALL_SCENE_CAPACITY);
    }
    if (plan.kernel.code) {
        const std::vector<SceneConstant> constants = sceneConstants(*plan.kernel.code);
        bytes.constants = sceneConstantValues(constants, packed);
        bytes.valuesInBuffer = plan.kernel.code->valuesInBuffer;
        for (const SceneConstant& constant : constants) {
            const std::uint32_t size = constant.real ? sizeof(Real) : sizeof(float);
            bytes.constantSizes.insert(bytes.constantSizes.end(), constant.components, size);
        }
    }
    bytes.frame = bytesOf(std::span(&packed.frame, 1));
    bytes.lights = BufferContents::of(std::move(packed.lights));
    bytes.nodes = nodesThenLooks(scene, plan, std::move(packed), packedInBuffer);
    return bytes;
}

PackedScene packFor(const Scene& scene, const RenderPlan& plan) {
    return plan.width == FloatWidth::F64 ? packBytes<double>(scene, plan) : packBytes<float>(scene, plan);
}

std::uint32_t groupsFor(std::uint32_t count) {
    return (count + WORKGROUP_SIZE - 1) / WORKGROUP_SIZE;
}

// How long one dispatch of `samples` rays may take before the device counts as hung. A real
// GPU's driver has its own watchdog (a hung GPU is reset and reported as device lost); this is
// the backstop for a driver that never signals, so it must exceed any honest dispatch on the
// slowest device, lavapipe on a busy machine: 60 s plus 1 µs per sample per (nodes + 1) x
// (lights + 1), some 80 times what lavapipe took on 2 loaded cores (about 12 ns), and
// proportional so huge or heavily sampled images are not cut off.
std::chrono::nanoseconds dispatchTimeout(const Scene& scene, std::uint64_t samples) {
    const double seconds =
        60.0 + 1e-6 * double(samples) * double(scene.nodes.size() + 1) * double(scene.lights.size() + 1);
    return std::chrono::nanoseconds(std::int64_t(std::min(seconds, 30.0 * 86400.0) * 1e9));
}

std::string mebibytes(std::uint64_t bytes) {
    return std::to_string((bytes + (std::uint64_t{1} << 20) - 1) >> 20) + " MiB";
}

// What the scene's buffers hold on the host (and again on the device): its nodes and lights in the
// plan's width, and the candidate lists with their sphere records.
std::uint64_t gpuSceneBytes(const Scene& scene, const RenderPlan& plan) {
    const bool f64 = plan.width == FloatWidth::F64;
    std::uint64_t bytes = scene.nodes.size() * (f64 ? sizeof(gpu::GpuNode<double>) : sizeof(gpu::GpuNode<float>)) +
                          scene.lights.size() * (f64 ? sizeof(gpu::GpuLight<double>) : sizeof(gpu::GpuLight<float>));
    if (const CandidateLists* lists = plan.candidates.get()) {
        const std::size_t record = f64 ? gpu::kCandidateSphereBytes<double> : gpu::kCandidateSphereBytes<float>;
        bytes += lists->sphereNodes.size() * record +
                 (lists->cellStarts.size() + lists->entries.size()) * sizeof(std::uint32_t) + lists->gridByteCount();
    }
    return bytes;
}

// work(), which packs or uploads the scene: running out of host or device memory there is the
// scene's size, not the image's.
template <typename Work>
decltype(auto) holdingScene(const Scene& scene, const RenderPlan& plan, Work&& work) {
    const auto what = [&] {
        return "the scene's " + sceneContents(scene) + " need about " + mebibytes(gpuSceneBytes(scene, plan)) +
               " in the GPU's buffers, and the candidate lists as much again on the host (try --backend cpu)";
    };
    try {
        return holding(what, work);
    } catch (const VulkanError& error) {
        if (error.failure() != VulkanFailure::OutOfMemory) {
            throw;
        }
        throw VulkanError(VulkanFailure::OutOfMemory, error.reason() + ": " + what());
    }
}

// Runs `leak` on destruction when the context's device hung.
struct LeakIfAbandoned {
    const VulkanContext& context;
    std::function<void()> leak;
    ~LeakIfAbandoned() {
        if (context.abandoned()) {
            leak();
        }
    }
};

}  // namespace

GpuRenderer::GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes, KernelCache kernelCache,
                         KeptKernels kept)
    : context_(context),
      maxBandBytes_(maxBandBytes),
      kernels_(std::move(kernelCache), kept.generatedKernels),
      uniformScene_{createSetLayout(context.device(), true), nullptr},
      texelScene_{createSetLayout(context.device(), false), nullptr},
      pipelines_(kept.pipelines),
      commandPool_(context.device(), vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                               context.queueFamily())),
      timestamps_(nullptr) {
    uniformScene_.pipelineLayout = createPipelineLayout(context.device(), uniformScene_.setLayout);
    texelScene_.pipelineLayout = createPipelineLayout(context.device(), texelScene_.setLayout);
    const auto families = context.physicalDevice().getQueueFamilyProperties();
    const std::uint32_t validBits = families[context.queueFamily()].timestampValidBits;
    if (validBits > 0) {
        timestamps_ = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2));
        nanosecondsPerTick_ = context.physicalDevice().getProperties().limits.timestampPeriod;
        timestampMask_ = validBits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << validBits) - 1;
    }
}

GpuRenderer::~GpuRenderer() {
    if (context_.abandoned()) {  // the hung work may still use them: see LeakIfAbandoned
        pipelines_.forEach([](vk::raii::Pipeline& pipeline) { pipeline.release(); });
        for (SceneBindings* bindings : {&uniformScene_, &texelScene_}) {
            bindings->pipelineLayout.release();
            bindings->setLayout.release();
        }
        timestamps_.release();
        commandPool_.release();
    }
}

DeviceAbilities GpuRenderer::abilities() const {
    const DeviceInfo& device = context_.selected();
    return DeviceAbilities{device.name, device.hasFloat64, device.maxTexelBufferElements};
}

RenderPlan GpuRenderer::plan(const Scene& scene, const PlanRequest& request) const {
    const auto what = [&] {
        const std::uint64_t lists = (candidates::kMaxEntries + candidates::kMaxCells) * sizeof(std::uint32_t) +
                                    (1 + gpu::CUBE_FACES * scene.lights.size()) * sizeof(gpu::GpuCandidateGrid);
        return "the scene's " + sceneContents(scene) + ": planning their candidate lists for the GPU (up to " +
               mebibytes(lists) + ")";
    };
    return holding(what, [&] { return planRender(scene, request, abilities()); });
}

Precision GpuRenderer::resolve(const Scene& scene, Precision requested) const {
    return resolvePrecision(scene, requested, abilities());
}

const vk::raii::Pipeline& GpuRenderer::pipeline(std::span<const std::uint32_t> spirv, std::uint64_t generatedId,
                                                SceneLayout layout, const gpu::Specialization& specialization,
                                                std::span<const std::byte> sceneValues,
                                                std::span<const std::uint32_t> sceneSizes) {
    const bool uniform = layout == SceneLayout::Uniform;
    PipelineKey key{generatedId ? nullptr : spirv.data(),
                    generatedId,
                    uniform,
                    specialization,
                    {sceneValues.begin(), sceneValues.end()}};
    if (const vk::raii::Pipeline* found = pipelines_.find(key)) {
        return *found;
    }
    const SpecializationData data = specializationData(specialization, sceneValues, sceneSizes);
    ++pipelinesCreated_;
    return pipelines_.insert(std::move(key),
                             createPipeline(context_.device(), bindings(layout).pipelineLayout, spirv, data));
}

const vk::raii::Pipeline& GpuRenderer::kernelPipeline(const Kernel& kernel, KernelBuild& build, SceneLayout layout,
                                                      const gpu::Specialization& specialization,
                                                      std::span<const std::byte> sceneValues,
                                                      std::span<const std::uint32_t> sceneSizes) {
    std::span<const std::uint32_t> spirv = kernels_.spirv(kernel, &build);
    try {
        return pipeline(spirv, build.generatedId, layout, specialization, sceneValues, sceneSizes);
    } catch (const vk::SystemError& error) {
        if (!kernels_.fromDiskCache(spirv.data())) {
            throw;
        }
        // The cached SPIR-V is a miss after all: its pipelines go with it, and glslang compiles it afresh.
        const std::uint64_t refused = build.generatedId;
        pipelines_.eraseIf([&](const PipelineKey& key, const auto&) { return std::get<1>(key) == refused; });
        KernelBuild fresh;
        spirv = kernels_.recompile(kernel, std::string("the driver refused its SPIR-V (") + error.what() + ")", &fresh);
        build.compileMilliseconds += fresh.compileMilliseconds;
        build.fromDiskCache = false;
        build.generatedId = fresh.generatedId;
        return pipeline(spirv, build.generatedId, layout, specialization, sceneValues, sceneSizes);
    }
}

void GpuRenderer::releaseGeneratedKernels() {
    pipelines_.eraseIf([](const PipelineKey& key, const auto&) { return std::get<1>(key) != 0; });
    kernels_.forgetGenerated();
}

GpuRenderResult GpuRenderer::render(const Scene& scene, const RenderPlan& plan, GpuOutput output) {
    GpuRenderResult result;
    const auto keep = [&](const GpuRenderResult& streamed) {
        result.precision = streamed.precision;
        result.timing = streamed.timing;
        result.usedCandidateLists = streamed.usedCandidateLists;
    };
    if (output == GpuOutput::Encoded8) {
        result.encoded = Rgb8Image{scene.image.width, scene.image.height, {}};
        result.encoded.bytes.reserve(std::size_t(scene.image.width) * scene.image.height * 3);
        keep(renderEncodedRows(scene, plan, [&](std::uint32_t, auto rgbRows) {
            result.encoded.bytes.insert(result.encoded.bytes.end(), rgbRows.begin(), rgbRows.end());
        }));
        return result;
    }
    const bool aov = output == GpuOutput::LinearClassesAndAov;
    const std::size_t pixels = std::size_t(scene.image.width) * scene.image.height;
    result.image = Image(scene.image.width, scene.image.height);
    result.classes.reserve(pixels);
    result.depth.reserve(aov ? pixels : 0);
    result.normals.reserve(aov ? pixels : 0);
    const auto append = [](auto& whole, const auto& band) { whole.insert(whole.end(), band.begin(), band.end()); };
    keep(renderLinearRows(scene, plan, output, [&](std::uint32_t firstRow, const GpuRenderResult& band) {
        std::copy(band.image.pixels.begin(), band.image.pixels.end(),
                  result.image.pixels.begin() + std::ptrdiff_t(firstRow) * scene.image.width);
        append(result.classes, band.classes);
        append(result.depth, band.depth);
        append(result.normals, band.normals);
    }));
    return result;
}

GpuRenderResult GpuRenderer::renderLinearRows(const Scene& scene, const RenderPlan& plan, GpuOutput output,
                                              const BandConsumer& consume, RowRange rowRange) {
    GpuRenderResult result;
    const std::uint32_t width = scene.image.width;
    const bool aov = output == GpuOutput::LinearClassesAndAov;
    const double scale = plan.placement.scale;  // the shader's t is in the placement's units
    GpuRenderResult rows;                       // reused from band to band
    renderBands(
        scene, plan, output, result,
        [&](const Band& band) {
            const std::size_t count = std::size_t(band.rows) * width;
            rows.image.width = width;
            rows.image.height = band.rows;
            rows.image.pixels.resize(count);
            std::transform(band.pixels, band.pixels + count, rows.image.pixels.begin(),
                           [](const GpuPixel& p) { return glm::vec3(p); });
            rows.classes.resize(count);
            std::transform(band.classes, band.classes + count, rows.classes.begin(), [](const GpuPixelClass& c) {
                return PixelClass{c.x, c.y};
            });
            rows.depth.resize(aov ? count : 0);
            rows.normals.resize(aov ? count : 0);
            for (std::size_t i = 0; aov && i < count; ++i) {
                const bool background = band.classes[i].x == PixelClass::kBackground;
                rows.depth[i] =
                    background ? std::numeric_limits<float>::infinity() : float(double(band.aovs[i].w) * scale);
                rows.normals[i] = glm::vec3(band.aovs[i]);
            }
            consume(band.firstRow, rows);
        },
        rowRange);
    return result;
}

GpuRenderResult GpuRenderer::renderEncodedRows(const Scene& scene, const RenderPlan& plan, const RowConsumer& consume,
                                               RowRange rows) {
    GpuRenderResult result;
    std::vector<std::uint8_t> rgb;
    renderBands(
        scene, plan, GpuOutput::Encoded8, result,
        [&](const Band& band) {
            const std::size_t count = std::size_t(band.rows) * scene.image.width;
            rgb.resize(count * 3);
            for (std::size_t i = 0; i < count; ++i) {
                std::memcpy(&rgb[3 * i], &band.encoded[i], 3);  // RGBA8, R in the lowest byte: drop A
            }
            consume(band.firstRow, rgb);
        },
        rows);
    return result;
}

namespace {

// One invocation traces a pixel: its loops cannot be split between dispatches (loop_budget.h).
void requireTraceWithinLoopLimit(const RenderPlan& plan, const std::string& device) {
    if (plan.tracePasses > plan.loopPassLimit) {
        throw PlanRefused(Refusal::PastLoopLimit,
                          "tracing a pixel of this scene may need " + std::to_string(plan.tracePasses) +
                              " loop passes in one invocation, and " + device + " ends a shader's loops after " +
                              std::to_string(plan.loopPassLimit) + " in all: the trace would be wrong",
                          "use --backend cpu");
    }
}

std::uint32_t outputModeFor(const Scene& scene, GpuOutput output, bool tracing) {
    if (tracing)
        return gpu::OUTPUT_TRACE;
    switch (output) {
        case GpuOutput::LinearAndClasses:
            return gpu::OUTPUT_LINEAR_AND_CLASSES;
        case GpuOutput::LinearClassesAndAov:
            return gpu::OUTPUT_LINEAR_CLASSES_AND_AOV;
        case GpuOutput::Encoded8:
            break;
    }
    return scene.image.encoding == Encoding::Srgb ? gpu::OUTPUT_8BIT_SRGB : gpu::OUTPUT_8BIT_LINEAR;
}

// The specialization constants of a render by `plan`: its output mode, its samples, whether its
// lights come in batches, and the plan's choice of sphere tests.
gpu::Specialization specializationFor(const Scene& scene, const RenderPlan& plan, std::uint32_t outputMode,
                                      bool batched) {
    return {outputMode, scene.image.samplesPerPixel, batched, plan.fastCameraTests, plan.fastShadowTests};
}

}  // namespace

GpuPixelTrace GpuRenderer::tracePixel(const Scene& scene, const RenderPlan& plan, std::uint32_t x, std::uint32_t y,
                                      std::uint32_t sample) {
    requireTraceWithinLoopLimit(plan, context_.selected().name);
    const std::vector<std::byte> request = traceRequest(scene, plan.width, x, y, sample);
    GpuPixelTrace trace;
    GpuRenderResult bands;
    const auto unpack = [&](const Band& band) { trace = unpackTrace(scene, plan.width, band.trace, plan.placement); };
    renderBands(scene, plan, GpuOutput::LinearAndClasses, bands, unpack, RowRange{}, request);
    trace.precision = plan.precision;
    trace.usedCandidateLists = bands.usedCandidateLists;
    if (plan.fallback && trace.inDoubt) {
        GpuPixelTrace again = tracePixel(scene, *plan.fallback, x, y, sample);
        again.precision = plan.precision;
        again.tracedAgainInF64 = true;
        again.inDoubt = true;
        return again;
    }
    return trace;
}

namespace {

// One dispatch of a band: which pipeline, the push constants, and its workgroups.
struct Dispatch {
    const vk::raii::Pipeline* pipeline;
    GpuBand band;
    std::uint32_t groupsX;
    std::uint32_t groupsY;
};

// Each tile class's tiles in the rows [firstRow, firstRow + rows), band-relative, one class after
// the other; `firsts[c]` is where class c's start and `counts[c]` how many it has.
struct BandTiles {
    std::vector<glm::uvec2> tiles;
    std::vector<std::uint32_t> firsts;
    std::vector<std::uint32_t> counts;
};

BandTiles bandTiles(const TileClassification& classification, std::uint32_t firstRow, std::uint32_t rows) {
    const std::uint32_t firstTileRow = firstRow / WORKGROUP_SIZE;
    const std::uint32_t tileRows = groupsFor(rows);
    std::vector<std::vector<glm::uvec2>> byClass(classification.classes.size());
    for (std::uint32_t y = 0; y < tileRows; ++y) {
        for (std::uint32_t x = 0; x < classification.tilesX; ++x) {
            const std::uint32_t tile = (firstTileRow + y) * classification.tilesX + x;
            byClass[classification.classOfTile[tile]].emplace_back(x, y);
        }
    }
    BandTiles band;
    for (const std::vector<glm::uvec2>& tiles : byClass) {
        band.firsts.push_back(std::uint32_t(band.tiles.size()));
        band.counts.push_back(std::uint32_t(tiles.size()));
        band.tiles.insert(band.tiles.end(), tiles.begin(), tiles.end());
    }
    return band;
}

// What the dispatches of every band share: the kernels' pipelines (the plan's, or one per tile
// class), the tiles' classification, and each pixel's work in shares, one dispatch each (the
// data-driven kernel's light batches; otherwise one share, all of it).
struct BandWork {
    std::vector<const vk::raii::Pipeline*> pipelines;
    const TileClassification* classification = nullptr;
    std::vector<PixelWork> shares;
    std::uint32_t width = 0;
};

// The dispatches of the band [firstRow, firstRow + rows): the whole grid of tiles once per share,
// or each tile class's listed tiles with its kernel (the lists uploaded to `tileBuffer` here).
std::vector<Dispatch> bandDispatches(const BandWork& work, std::uint32_t firstRow, std::uint32_t rows,
                                     HostVisibleBuffer& tileBuffer) {
    std::vector<Dispatch> dispatches;
    if (!work.classification) {
        for (const PixelWork& share : work.shares) {
            const GpuBand band{firstRow,         rows,           0, share.firstSample, share.endSample,
                               share.firstLight, share.endLight, 0};
            dispatches.push_back({work.pipelines[0], band, groupsFor(work.width), groupsFor(rows)});
        }
        return dispatches;
    }
    const PixelWork& all = work.shares.front();
    const BandTiles tiles = bandTiles(*work.classification, firstRow, rows);
    tileBuffer.upload(std::as_bytes(std::span(tiles.tiles)));
    for (std::size_t c = 0; c < work.pipelines.size(); ++c) {
        if (tiles.counts[c] > 0) {
            const GpuBand band{firstRow, rows, tiles.firsts[c], 0, all.endSample, 0, all.endLight, 0};
            dispatches.push_back({work.pipelines[c], band, tiles.counts[c], 1});
        }
    }
    return dispatches;
}

// One workgroup of each kernel, so that the driver's compile of it (lavapipe JITs at the first
// dispatch) is not counted as render time: of the first share, which reads nothing carried.
std::vector<Dispatch> warmUpDispatches(std::vector<Dispatch> dispatches) {
    std::erase_if(dispatches, [](const Dispatch& dispatch) {
        return dispatch.band.firstSample > 0 || dispatch.band.firstLight > 0;
    });
    for (Dispatch& dispatch : dispatches) {
        dispatch.groupsX = dispatch.groupsY = 1;
    }
    return dispatches;
}

// The band buffer's pixels from `offset` on (null for a buffer this render does not fill).
template <typename Pixel>
Pixel* pixelsFrom(const HostVisibleBuffer& buffer, std::size_t offset) {
    auto* first = reinterpret_cast<Pixel*>(buffer.data());
    return first ? first + offset : nullptr;
}

// What one render writes and how large its bands are.
struct BandShape {
    bool linear;         // pixels and classes (else the encoded image)
    bool aov;            // and the AOVs
    bool batched;        // light batches: the carry buffer
    std::uint32_t rows;  // per band
    std::size_t pixels;  // per band
    std::size_t tiles;   // per band, when tile classes list their tiles
};

// Large images render in bands of rows so the pixel buffer (and the light batches' carry) stays
// within `limit` bytes; a band is whole rows of tiles.
// `batched`: a band takes several dispatches that carry what a pixel has so far.
BandShape bandShape(const Scene& scene, GpuOutput output, bool tracing, bool batched, bool tiled,
                    vk::DeviceSize limit) {
    const std::uint32_t width = scene.image.width;
    const std::uint32_t height = scene.image.height;
    const vk::DeviceSize rowBytes =
        vk::DeviceSize{width} * (sizeof(GpuPixel) + (batched ? sizeof(gpu::GpuPixelCarry) : 0));
    const std::uint32_t fitting = std::uint32_t(std::clamp<vk::DeviceSize>(limit / rowBytes, 1, height));
    const std::uint32_t rows =
        fitting >= height ? height : std::max(WORKGROUP_SIZE, fitting / WORKGROUP_SIZE * WORKGROUP_SIZE);
    return {output != GpuOutput::Encoded8 && !tracing,
            output == GpuOutput::LinearClassesAndAov && !tracing,
            batched,
            rows,
            std::size_t(rows) * width,
            tiled ? std::size_t(groupsFor(width)) * groupsFor(rows) : 0};
}

// A render's buffers with its descriptor set, command buffer and fence: created together,
// destroyed together, or after a hang left together to the device (abandon(), LeakIfAbandoned).
struct BandBuffers {
    HostVisibleBuffer frame;
    TexelBuffer nodes, lights;  // bound as the scene's layout asks (descriptorType)
    HostVisibleBuffer pixels, classes, encoded, aov, trace, tiles, carry, sceneValues;
    CandidateBuffers candidates;
    vk::raii::DescriptorPool pool = nullptr;
    vk::raii::DescriptorSets sets = nullptr;
    vk::raii::CommandBuffers commandBuffers = nullptr;
    vk::raii::Fence done = nullptr;

    // The storage and uniform buffers in binding order (shader_interface.h); the texel buffers
    // are bound on their own.
    std::array<HostVisibleBuffer*, gpu::BINDING_COUNT> byBinding() {
        return {&frame, nullptr, nullptr, &pixels, &classes, &encoded, nullptr,     nullptr,
                &aov,   &trace,  &tiles,  nullptr, nullptr,  &carry,   &sceneValues};
    }
    void abandon() {
        for (HostVisibleBuffer* buffer : byBinding()) {
            if (buffer) {
                buffer->abandon();
            }
        }
        nodes.abandon();
        lights.abandon();
        candidates.abandon();
        sets[0].release();
        pool.release();
        commandBuffers[0].release();
        done.release();
    }
};

// The rows [firstRow + skipped, firstRow + rows) of a band of `width` pixels, as `buffers` hold them.
RenderedBand bandOf(const BandBuffers& buffers, std::uint32_t width, std::uint32_t firstRow, std::uint32_t rows,
                    std::uint32_t skipped) {
    const std::size_t at = std::size_t(skipped) * width;
    return {firstRow + skipped,
            rows - skipped,
            pixelsFrom<GpuPixel>(buffers.pixels, at),
            pixelsFrom<GpuPixelClass>(buffers.classes, at),
            pixelsFrom<GpuEncodedPixel>(buffers.encoded, at),
            pixelsFrom<GpuAovPixel>(buffers.aov, at),
            buffers.trace.data()};
}

// The descriptor set of `buffers`, every binding written; the command buffer and fence.
void bindBandBuffers(BandBuffers& buffers, const vk::raii::Device& device, const vk::raii::CommandPool& commandPool,
                     const vk::raii::DescriptorSetLayout& setLayout, bool uniformScene) {
    const std::array<vk::DescriptorPoolSize, 3> poolSizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, gpu::BINDING_COUNT),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, gpu::BINDING_COUNT),
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformTexelBuffer, gpu::BINDING_COUNT)};
    buffers.pool = vk::raii::DescriptorPool(
        device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSizes));
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    buffers.sets = vk::raii::DescriptorSets(device, vk::DescriptorSetAllocateInfo(*buffers.pool, layouts));
    const vk::raii::DescriptorSet& set = buffers.sets[0];
    buffers.candidates.write(device, set);
    buffers.nodes.bind(device, set, gpu::NODE_BINDING, descriptorType(gpu::NODE_BINDING, uniformScene));
    buffers.lights.bind(device, set, gpu::LIGHT_BINDING, descriptorType(gpu::LIGHT_BINDING, uniformScene));
    const auto byBinding = buffers.byBinding();
    for (std::uint32_t binding = 0; binding < gpu::BINDING_COUNT; ++binding) {
        if (const HostVisibleBuffer* buffer = byBinding[binding]) {
            const vk::DescriptorBufferInfo info(*buffer->buffer(), 0, buffer->size());
            device.updateDescriptorSets(
                vk::WriteDescriptorSet(*set, binding, 0, descriptorType(binding, uniformScene), nullptr, info),
                nullptr);
        }
    }
    buffers.commandBuffers = vk::raii::CommandBuffers(
        device, vk::CommandBufferAllocateInfo(*commandPool, vk::CommandBufferLevel::ePrimary, 1));
    buffers.done = vk::raii::Fence(device, vk::FenceCreateInfo());
}

// Records `dispatches` into `commands`, each after the writes of the one before; returns the
// samples they render, for the hang timeout.
std::uint64_t recordDispatches(const vk::raii::CommandBuffer& commands, const vk::raii::PipelineLayout& layout,
                               std::span<const Dispatch> dispatches) {
    std::uint64_t samples = 0;
    for (std::size_t i = 0; i < dispatches.size(); ++i) {
        const Dispatch& dispatch = dispatches[i];
        if (i > 0) {
            // The classes write different pixels of the same buffers: ordered all the same. A
            // light batch reads and writes what the one before it carried.
            const vk::MemoryBarrier between(vk::AccessFlagBits::eShaderWrite,
                                            vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
            commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                                     vk::PipelineStageFlagBits::eComputeShader, {}, between, nullptr, nullptr);
        }
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, **dispatch.pipeline);
        commands.pushConstants<GpuBand>(*layout, vk::ShaderStageFlagBits::eCompute, 0, dispatch.band);
        commands.dispatch(dispatch.groupsX, dispatch.groupsY, 1);
        samples += std::uint64_t(dispatch.groupsX) * dispatch.groupsY * WORKGROUP_SIZE * WORKGROUP_SIZE *
                   (dispatch.band.endSample - dispatch.band.firstSample);
    }
    return samples;
}

// A render's buffers, the scene's uploaded (running out of memory there is the scene's size) and
// the request of a traced pixel, bound to a descriptor set of `setLayout`.
BandBuffers makeBandBuffers(const VulkanContext& context, const vk::raii::CommandPool& commandPool,
                            const vk::raii::DescriptorSetLayout& setLayout, const Scene& scene, const RenderPlan& plan,
                            PackedScene& packed, const BandShape& shape, std::span<const std::byte> traceRequest) {
    const vk::raii::Device& device = context.device();
    const vk::raii::PhysicalDevice& physicalDevice = context.physicalDevice();
    const bool uniformScene = plan.layout == SceneLayout::Uniform;
    const vk::BufferUsageFlags storage = vk::BufferUsageFlagBits::eStorageBuffer;
    // Written as soon as made, and what the host held released: the buffers are made in order.
    const auto sceneBuffer = [&](BufferContents& contents) {
        TexelBuffer buffer = holdingScene(scene, plan, [&] {
            return TexelBuffer(device, physicalDevice, contents.size(), vk::Format::eR32G32B32A32Uint,
                               vk::BufferUsageFlagBits::eUniformBuffer);
        });
        contents.writeTo(buffer.buffer().data());
        contents.release();
        return buffer;
    };
    // Only the output mode's buffers get their full size; the others are bound but never written.
    const auto output = [&](bool used, std::size_t bytesPerPixel) {
        return HostVisibleBuffer(device, physicalDevice, used ? shape.pixels * bytesPerPixel : 0, storage);
    };
    const bool encoded = !shape.linear && traceRequest.empty();
    BandBuffers buffers{
        HostVisibleBuffer(device, physicalDevice, packed.frame.size(), vk::BufferUsageFlagBits::eUniformBuffer),
        sceneBuffer(packed.nodes),
        sceneBuffer(packed.lights),
        output(shape.linear, sizeof(GpuPixel)),
        output(shape.linear, sizeof(GpuPixelClass)),
        output(encoded, sizeof(gpu::GpuEncodedPixel)),
        output(shape.aov, sizeof(gpu::GpuAovPixel)),
        HostVisibleBuffer(device, physicalDevice, traceRequest.size(), storage),
        HostVisibleBuffer(device, physicalDevice, shape.tiles * sizeof(glm::uvec2), storage),
        output(shape.batched, sizeof(gpu::GpuPixelCarry)),
        HostVisibleBuffer(device, physicalDevice, packed.bufferedValues().size(), storage),
        holdingScene(scene, plan, [&] {
            return CandidateBuffers(device, physicalDevice, plan.candidates, packed.candidateSpheres,
                                    context.selected().hostImportAlignment);
        })};
    packed.candidateSpheres.release();
    buffers.trace.upload(traceRequest);
    buffers.frame.upload(std::span(packed.frame));
    buffers.sceneValues.upload(packed.bufferedValues());
    bindBandBuffers(buffers, device, commandPool, setLayout, uniformScene);
    return buffers;
}

// The device's timestamps (a null pool: none), to time dispatches by.
struct Timestamps {
    const vk::raii::QueryPool& pool;
    std::uint64_t mask;
    double nanosecondsPerTick;
};

// Records, submits and waits for `dispatches`; returns their duration in milliseconds (`timed`:
// by the device's timestamps where it has them).
double submitBand(const VulkanContext& context, const Timestamps& timestamps, BandBuffers& buffers,
                  const vk::raii::PipelineLayout& pipelineLayout, const Scene& scene,
                  std::span<const Dispatch> dispatches, bool timed) {
    const vk::raii::QueryPool& timestamps_ = timestamps.pool;
    const bool useTimestamps = timed && *timestamps_;
    const vk::raii::CommandBuffer& commands = buffers.commandBuffers[0];
    commands.reset();
    commands.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    if (useTimestamps) {
        commands.resetQueryPool(*timestamps_, 0, 2);
        commands.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *timestamps_, 0);
    }
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipelineLayout, 0, *buffers.sets[0], nullptr);
    const std::uint64_t samples = recordDispatches(commands, pipelineLayout, dispatches);
    if (useTimestamps) {
        commands.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *timestamps_, 1);
    }
    // The shader's writes must be visible to the host's reads of the mapped buffers.
    const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, toHost,
                             nullptr, nullptr);
    commands.end();

    const auto start = std::chrono::steady_clock::now();
    context.submitAndWait(commands, buffers.done, dispatchTimeout(scene, samples));  // throws VulkanError
    context.device().resetFences(*buffers.done);
    const double wallMilliseconds = millisecondsSince(start);
    if (!useTimestamps) {
        return wallMilliseconds;
    }
    const auto [status, ticks] =
        timestamps_.getResults<std::uint64_t>(0, 2, 2 * sizeof(std::uint64_t), sizeof(std::uint64_t),
                                              vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    return double((ticks[1] - ticks[0]) & timestamps.mask) * timestamps.nanosecondsPerTick * 1e-6;
}

}  // namespace

std::vector<const vk::raii::Pipeline*> GpuRenderer::pipelinesFor(
    std::span<const Kernel> kernels, const RenderPlan& plan, const gpu::Specialization& specialization,
    std::span<const std::byte> sceneValues, std::span<const std::uint32_t> sceneSizes, KernelBuild& timing) {
    std::vector<const vk::raii::Pipeline*> pipelines;
    for (const Kernel& kernel : kernels) {
        KernelBuild build;
        pipelines.push_back(&kernelPipeline(kernel, build, plan.layout, specialization, sceneValues, sceneSizes));
        timing.generateMilliseconds += build.generateMilliseconds;
        timing.compileMilliseconds += build.compileMilliseconds;
        timing.loadMilliseconds += build.loadMilliseconds;
        timing.fromDiskCache = build.fromDiskCache;
    }
    return pipelines;
}

void GpuRenderer::renderBands(const Scene& scene, const RenderPlan& plan, GpuOutput output, GpuRenderResult& result,
                              const std::function<void(const Band&)>& consume, RowRange rowRange,
                              std::span<const std::byte> traceRequest) {
    const bool tracing = !traceRequest.empty();
    const bool batched = plan.lightBatches.splits() && !tracing;  // a traced pixel is one dispatch
    const gpu::Specialization specialization =
        specializationFor(scene, plan, outputModeFor(scene, output, tracing), batched);
    const auto uploadStart = std::chrono::steady_clock::now();
    PackedScene packed = holdingScene(scene, plan, [&] { return packFor(scene, plan); });
    result.precision = plan.precision;
    result.usedCandidateLists = plan.layout == SceneLayout::TexelsCandidates;
    // The kernels: the plan's, or (culling, not for a traced pixel) one per tile class.
    const TileClassification* classification = tracing ? nullptr : plan.tileClasses.classification.get();
    const std::span<const Kernel> kernels =
        classification ? std::span<const Kernel>(plan.tileClasses.kernels) : std::span<const Kernel>(&plan.kernel, 1);
    const std::uint32_t lightCount = std::uint32_t(scene.lights.size());
    const BandWork work{
        pipelinesFor(kernels, plan, specialization, packed.specValues(), packed.specSizes(), result.timing.kernel),
        classification, plan.lightBatches.work(scene.image.samplesPerPixel, lightCount), scene.image.width};
    const vk::DeviceSize bandBytes =
        std::min<vk::DeviceSize>(context_.physicalDevice().getProperties().limits.maxStorageBufferRange, maxBandBytes_);
    const BandShape shape = bandShape(scene, output, tracing, batched, classification != nullptr, bandBytes);
    const SceneBindings& sceneBindings = bindings(plan.layout);
    BandBuffers buffers =
        makeBandBuffers(context_, commandPool_, sceneBindings.setLayout, scene, plan, packed, shape, traceRequest);
    result.timing.uploadMilliseconds = millisecondsSince(uploadStart);
    // Destroyed first when a hang unwinds this scope: the hung dispatch may still be using the
    // buffers, so they are leaked with the device instead (VulkanContext::abandoned()).
    const LeakIfAbandoned leakIfAbandoned{context_, [&] { buffers.abandon(); }};
    const Timestamps timestamps{timestamps_, timestampMask_, nanosecondsPerTick_};
    const auto run = [&](std::span<const Dispatch> dispatches, bool timed) {
        return submitBand(context_, timestamps, buffers, sceneBindings.pipelineLayout, scene, dispatches, timed);
    };
    GpuTiming& timing = result.timing;
    timing.fromTimestamps = static_cast<bool>(*timestamps_);
    if (tracing) {
        // One invocation does the work; the pixel is in the request, not in the dispatch.
        const Dispatch trace{work.pipelines[0], GpuBand{0, 1, 0, 0, scene.image.samplesPerPixel, 0, lightCount, 0}, 1,
                             1};
        timing.renderMilliseconds = run(std::span(&trace, 1), false);
        consume(Band{0, 0, nullptr, nullptr, nullptr, nullptr, buffers.trace.data()});
        return;
    }
    const std::uint32_t height = scene.image.height;
    timing.firstDispatchMilliseconds =
        run(warmUpDispatches(bandDispatches(work, 0, std::min(shape.rows, height), buffers.tiles)), false);
    // Bands start on a tile row, so each tile is one of the classification's (a range of rows
    // that starts inside a tile renders that tile whole and hands on only the range's rows).
    const std::uint32_t endRow = std::min(rowRange.end(), height);
    const std::uint32_t startRow = std::min(rowRange.first, endRow) / WORKGROUP_SIZE * WORKGROUP_SIZE;
    for (std::uint32_t firstRow = startRow; firstRow < endRow; firstRow += shape.rows) {
        const std::uint32_t rows = std::min(shape.rows, endRow - firstRow);
        timing.renderMilliseconds += run(bandDispatches(work, firstRow, rows, buffers.tiles), true);
        if (plan.fallback) {
            renderPixelsInDoubt(scene, *plan.fallback, output, bandOf(buffers, scene.image.width, firstRow, rows, 0),
                                result);
        }
        consume(bandOf(buffers, scene.image.width, firstRow, rows, std::max(firstRow, rowRange.first) - firstRow));
    }
}

namespace {

// The pixels of a band that a certified kernel left in doubt, in rows of the whole image, with their
// places in the band; and how many of the band's vectors (8-pixel rows of a tile, the lanes lavapipe
// runs together) hold one, of how many.
struct PixelsInDoubt {
    std::vector<glm::uvec2> pixels;
    std::vector<std::size_t> places;
    std::uint64_t vectors = 0;
    std::uint64_t totalVectors = 0;
};

template <typename Pixel, typename InDoubt>
PixelsInDoubt findPixelsInDoubt(const Pixel* band, std::uint32_t width, std::uint32_t firstRow, std::uint32_t rows,
                                InDoubt inDoubt) {
    PixelsInDoubt found;
    for (std::uint32_t y = 0; y < rows; ++y) {
        for (std::uint32_t vectorStart = 0; vectorStart < width; vectorStart += WORKGROUP_SIZE) {
            bool vectorInDoubt = false;
            for (std::uint32_t x = vectorStart; x < std::min(width, vectorStart + WORKGROUP_SIZE); ++x) {
                const std::size_t place = std::size_t(y) * width + x;
                if (inDoubt(band[place])) {
                    found.pixels.emplace_back(x, firstRow + y);
                    found.places.push_back(place);
                    vectorInDoubt = true;
                }
            }
            found.vectors += vectorInDoubt ? 1 : 0;
        }
    }
    found.totalVectors = std::uint64_t(rows) * groupsFor(width);
    return found;
}

// The listed render's results, each into its pixel's place in the band.
void mergeListed(const BandBuffers& listed, std::span<const std::size_t> places, GpuOutput output, GpuPixel* pixels,
                 GpuPixelClass* classes, gpu::GpuEncodedPixel* encoded, gpu::GpuAovPixel* aovs) {
    for (std::size_t i = 0; i < places.size(); ++i) {
        const std::size_t place = places[i];
        if (output == GpuOutput::Encoded8) {
            encoded[place] = pixelsFrom<gpu::GpuEncodedPixel>(listed.encoded, 0)[i];
            continue;
        }
        pixels[place] = pixelsFrom<GpuPixel>(listed.pixels, 0)[i];
        classes[place] = pixelsFrom<GpuPixelClass>(listed.classes, 0)[i];
        if (output == GpuOutput::LinearClassesAndAov) {
            aovs[place] = pixelsFrom<gpu::GpuAovPixel>(listed.aov, 0)[i];
        }
    }
}

}  // namespace

void GpuRenderer::renderPixelsInDoubt(const Scene& scene, const RenderPlan& fallback, GpuOutput output,
                                      const Band& band, GpuRenderResult& result) {
    const std::uint32_t width = scene.image.width;
    PixelsInDoubt found =
        output == GpuOutput::Encoded8
            ? findPixelsInDoubt(band.encoded, width, band.firstRow, band.rows,
                                [](gpu::GpuEncodedPixel pixel) { return (pixel & ENCODED_ALPHA_BITS) == 0; })
            : findPixelsInDoubt(band.pixels, width, band.firstRow, band.rows,
                                [](const GpuPixel& pixel) { return pixel.w == 0.0f; });
    CertifiedFallback& stats = result.timing.fallback;
    stats.pixels += found.pixels.size();
    stats.totalPixels += std::uint64_t(band.rows) * width;
    stats.vectors += found.vectors;
    stats.totalVectors += found.totalVectors;
    if (!found.pixels.empty()) {
        // Whole workgroups, the padding past the image's width (the kernel skips it).
        constexpr std::size_t kGroup = WORKGROUP_SIZE * WORKGROUP_SIZE;
        const std::size_t listed = (found.pixels.size() + kGroup - 1) / kGroup * kGroup;
        found.pixels.resize(listed, glm::uvec2(UINT32_MAX));
        const gpu::Specialization specialization =
            specializationFor(scene, fallback, outputModeFor(scene, output, false), fallback.lightBatches.splits());
        PackedScene packed = packFor(scene, fallback);
        const vk::raii::Pipeline* pipeline =
            pipelinesFor(std::span(&fallback.kernel, 1), fallback, specialization, packed.specValues(),
                         packed.specSizes(), result.timing.kernel)[0];
        const BandShape shape{output != GpuOutput::Encoded8,
                              output == GpuOutput::LinearClassesAndAov,
                              false,
                              scene.image.height,
                              listed,
                              listed};
        const SceneBindings& sceneBindings = bindings(fallback.layout);
        BandBuffers buffers =
            makeBandBuffers(context_, commandPool_, sceneBindings.setLayout, scene, fallback, packed, shape, {});
        const LeakIfAbandoned leakIfAbandoned{context_, [&] { buffers.abandon(); }};
        buffers.tiles.upload(std::as_bytes(std::span(found.pixels)));
        const GpuBand all{
            0, scene.image.height, 0, 0, scene.image.samplesPerPixel, 0, std::uint32_t(scene.lights.size()), 0};
        const Dispatch warmUp{pipeline, all, 1, 1};
        const Dispatch dispatch{pipeline, all, std::uint32_t(listed / kGroup), 1};
        const Timestamps timestamps{timestamps_, timestampMask_, nanosecondsPerTick_};
        const auto run = [&](const Dispatch& one, bool timed) {
            return submitBand(context_, timestamps, buffers, sceneBindings.pipelineLayout, scene, std::span(&one, 1),
                              timed);
        };
        if (stats.pixels == found.pixels.size()) {  // the render's first pixels in doubt: warm up once
            result.timing.firstDispatchMilliseconds += run(warmUp, false);
        }
        result.timing.renderMilliseconds += run(dispatch, true);
        mergeListed(buffers, found.places, output, band.pixels, band.classes, band.encoded, band.aovs);
    }
}

}  // namespace hexray::gpu
