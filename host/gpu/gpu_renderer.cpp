#include "gpu/gpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>

#include "camera/camera.h"

#include "gpu/gpu_layout.h"
#include "gpu/gpu_scene.h"
#include "gpu/lecture_demo_ceiling.h"
#include "util/milliseconds_since.h"
#include "vulkan/host_visible_buffer.h"

namespace {
// SPIR-V generated from shaders/render.comp at build time, one array per precision variant
// and scene storage.
#include "kRenderF32BvhSpv.h"
#include "kRenderF32NaiveBvhSpv.h"
#include "kRenderF32NaiveStorageSpv.h"
#include "kRenderF32NaiveUniformSpv.h"
#include "kRenderF32StorageSpv.h"
#include "kRenderF32UniformSpv.h"
#include "kRenderF64BvhSpv.h"
#include "kRenderF64StorageSpv.h"
#include "kRenderF64UniformSpv.h"
#include "kLectureDemoCeilingSpv.h"
}  // namespace

namespace hexray {
namespace {

using gpu::GpuBand;
using gpu::GpuPixel;
using gpu::GpuPixelClass;
using gpu::kWorkgroupSize;

// Set 0's bindings: the storage-buffer layout adds the BVH's two.
constexpr std::array<std::uint32_t, 10> kAllBindings = {
    gpu::kFrameBinding,   gpu::kNodeBinding,    gpu::kLightBinding, gpu::kPixelBinding, gpu::kClassBinding,
    gpu::kEncodedBinding, gpu::kAovBinding,     gpu::kTraceBinding, gpu::kBvhBinding,   gpu::kPrimitiveBinding};

std::span<const std::uint32_t> bindingsOf(bool smallScene) {
    return std::span(kAllBindings).first(smallScene ? 8 : 10);
}

using Spirv = std::span<const std::uint32_t>;

using gpu::SceneLayout;

Spirv spirvFor(Precision precision, SceneLayout layout) {
    const auto pick = [layout](Spirv uniform, Spirv storage, Spirv bvh) {
        return layout == SceneLayout::Uniform ? uniform : layout == SceneLayout::Storage ? storage : bvh;
    };
    switch (precision) {
        case Precision::F32Naive:
            return pick(kRenderF32NaiveUniformSpv, kRenderF32NaiveStorageSpv, kRenderF32NaiveBvhSpv);
        case Precision::F64: return pick(kRenderF64UniformSpv, kRenderF64StorageSpv, kRenderF64BvhSpv);
        default: return pick(kRenderF32UniformSpv, kRenderF32StorageSpv, kRenderF32BvhSpv);
    }
}

// The frame, nodes and lights (bindings 0 to 2) come in uniform buffers for a small scene;
// the pixels and classes are always storage buffers.
vk::DescriptorType descriptorType(std::uint32_t binding, bool smallScene) {
    return smallScene && binding <= gpu::kLightBinding ? vk::DescriptorType::eUniformBuffer
                                                       : vk::DescriptorType::eStorageBuffer;
}

vk::raii::DescriptorSetLayout createSetLayout(const vk::raii::Device& device, bool smallScene) {
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding : bindingsOf(smallScene)) {
        bindings.emplace_back(binding, descriptorType(binding, smallScene), 1, vk::ShaderStageFlagBits::eCompute);
    }
    return vk::raii::DescriptorSetLayout(device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

vk::raii::PipelineLayout createPipelineLayout(const vk::raii::Device& device,
                                              const vk::raii::DescriptorSetLayout& setLayout) {
    const vk::PushConstantRange band(vk::ShaderStageFlagBits::eCompute, 0, sizeof(GpuBand));
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    return vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo({}, layouts, band));
}

// Specialization constants in id order: 0 and 1 the local size, 2 to 8 the scene's.
struct SpecializationData {
    std::uint32_t localSizeX = kWorkgroupSize;
    std::uint32_t localSizeY = kWorkgroupSize;
    gpu::ShaderSpecialization scene;
};

vk::raii::Pipeline createPipeline(const vk::raii::Device& device, const vk::raii::PipelineLayout& layout,
                                  Spirv spirv, const gpu::ShaderSpecialization& scene) {
    const vk::raii::ShaderModule module(device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
    const SpecializationData data{kWorkgroupSize, kWorkgroupSize, scene};
    constexpr std::uint32_t kConstants = sizeof(SpecializationData) / sizeof(std::uint32_t);
    std::array<vk::SpecializationMapEntry, kConstants> entries;
    for (std::uint32_t id = 0; id < kConstants; ++id) {
        entries[id] = vk::SpecializationMapEntry(id, id * sizeof(std::uint32_t), sizeof(std::uint32_t));
    }
    const vk::SpecializationInfo specialization(entries, vk::ArrayProxyNoTemporaries<const SpecializationData>(data));
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main",
                                                  &specialization);
    return vk::raii::Pipeline(device, nullptr, vk::ComputePipelineCreateInfo({}, stage, *layout));
}

// The scene in the chosen variant's layout, as the bytes the buffers receive.
struct PackedScene {
    std::vector<std::byte> frame;
    std::vector<std::byte> nodes;
    std::vector<std::byte> lights;
    std::vector<std::byte> bvhNodes;    // empty: no BVH
    std::vector<std::byte> primitives;
};

template <typename T>
std::vector<std::byte> bytesOf(std::span<T> values) {
    const auto bytes = std::as_bytes(values);
    return {bytes.begin(), bytes.end()};
}

// `bvh` (when given) is uploaded only if the shader's stack can walk it.
template <typename Real>
PackedScene packBytes(const Scene& scene, gpu::Placement placement, SceneLayout layout, const Bvh* bvh) {
    gpu::GpuScene<Real> packed = gpu::packScene<Real>(scene, placement);
    PackedScene bytes;
    if (bvh) {
        const gpu::GpuBvh<Real> tree = gpu::packBvh<Real>(scene, *bvh, packed);
        if (!tree.nodes.empty() && tree.depth <= gpu::kBvhStackSize) {
            bytes.bvhNodes = bytesOf(std::span(tree.nodes));
            bytes.primitives = bytesOf(std::span(tree.primitives));
        }
    }
    if (layout == SceneLayout::Uniform) {
        // A uniform block declares all kSmallSceneCapacity entries: the buffers must hold them.
        packed.nodes.resize(gpu::kSmallSceneCapacity);
        packed.lights.resize(gpu::kSmallSceneCapacity);
    }
    bytes.frame = bytesOf(std::span(&packed.frame, 1));
    bytes.nodes = bytesOf(std::span(packed.nodes));
    bytes.lights = bytesOf(std::span(packed.lights));
    return bytes;
}

PackedScene packFor(const Scene& scene, Precision precision, SceneLayout layout, const Bvh* bvh) {
    switch (precision) {
        case Precision::F64: return packBytes<double>(scene, gpu::Placement::CameraRelative, layout, bvh);
        case Precision::F32Naive: return packBytes<float>(scene, gpu::Placement::World, layout, bvh);
        default: return packBytes<float>(scene, gpu::Placement::CameraRelative, layout, bvh);
    }
}

std::uint32_t groupsFor(std::uint32_t count) {
    return (count + kWorkgroupSize - 1) / kWorkgroupSize;
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

GpuRenderer::GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes)
    : context_(context),
      maxBandBytes_(maxBandBytes),
      uniformScene_{createSetLayout(context.device(), true), nullptr},
      storageScene_{createSetLayout(context.device(), false), nullptr},
      commandPool_(context.device(),
                   vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, context.queueFamily())),
      timestamps_(nullptr) {
    uniformScene_.pipelineLayout = createPipelineLayout(context.device(), uniformScene_.setLayout);
    storageScene_.pipelineLayout = createPipelineLayout(context.device(), storageScene_.setLayout);
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
        for (auto& [key, pipeline] : pipelines_) {
            pipeline.release();
        }
        for (SceneBindings* bindings : {&uniformScene_, &storageScene_}) {
            bindings->pipelineLayout.release();
            bindings->setLayout.release();
        }
        timestamps_.release();
        commandPool_.release();
    }
}

Precision GpuRenderer::resolve(const Scene& scene, Precision requested) const {
    const bool hasFloat64 = context_.selected().hasFloat64;
    if (requested == Precision::Auto) {
        return choosePrecision(scene, hasFloat64);
    }
    if (requested == Precision::F64 && !hasFloat64) {
        throw VulkanError(VulkanFailure::NoFloat64,
                          "--precision f64 needs shaderFloat64, which " + context_.selected().name + " does not have",
                          "use --precision f32");
    }
    return requested;
}

const vk::raii::Pipeline& GpuRenderer::pipeline(const PipelineKey& key) {
    auto found = pipelines_.find(key);
    if (found == pipelines_.end()) {
        const auto& [kernel, precision, layout, specialization] = key;
        const Spirv spirv = kernel == Kernel::LectureDemoCeiling ? Spirv(kLectureDemoCeilingSpv)
                                                                 : spirvFor(precision, layout);
        found = pipelines_
                    .emplace(key, createPipeline(context_.device(), bindings(layout).pipelineLayout, spirv,
                                                 specialization))
                    .first;
    }
    return found->second;
}

GpuRenderResult GpuRenderer::render(const Scene& scene, Precision requested, GpuOutput output,
                                    Acceleration acceleration) {
    if (output == GpuOutput::Encoded8) {
        return renderEncoded(scene, resolve(scene, requested), Kernel::Renderer);
    }
    GpuRenderResult result;
    const bool aov = output == GpuOutput::LinearClassesAndAov;
    const std::size_t pixels = std::size_t(scene.image.width) * scene.image.height;
    result.image = Image(scene.image.width, scene.image.height);
    result.classes.reserve(pixels);
    result.depth.reserve(aov ? pixels : 0);
    result.normals.reserve(aov ? pixels : 0);
    const auto append = [](auto& whole, const auto& band) { whole.insert(whole.end(), band.begin(), band.end()); };
    const GpuRenderResult streamed = renderLinearRows(
        scene, requested, output,
        [&](std::uint32_t firstRow, const GpuRenderResult& band) {
            std::copy(band.image.pixels.begin(), band.image.pixels.end(),
                      result.image.pixels.begin() + std::ptrdiff_t(firstRow) * scene.image.width);
            append(result.classes, band.classes);
            append(result.depth, band.depth);
            append(result.normals, band.normals);
        },
        acceleration);
    result.precision = streamed.precision;
    result.timing = streamed.timing;
    result.usedBvh = streamed.usedBvh;
    return result;
}

GpuRenderResult GpuRenderer::renderLinearRows(const Scene& scene, Precision requested, GpuOutput output,
                                              const BandConsumer& consume, Acceleration acceleration) {
    GpuRenderResult result;
    result.precision = resolve(scene, requested);
    const std::uint32_t width = scene.image.width;
    const bool aov = output == GpuOutput::LinearClassesAndAov;
    // The shader's t is in the placement's units.
    const double scale = result.precision == Precision::F32Naive ? 1.0 : gpu::placementScale(scene);
    GpuRenderResult rows;  // reused from band to band
    renderBands(scene, result.precision, output, acceleration, Kernel::Renderer, result, [&](const Band& band) {
        const std::size_t count = std::size_t(band.rows) * width;
        rows.image.width = width;
        rows.image.height = band.rows;
        rows.image.pixels.resize(count);
        std::transform(band.pixels, band.pixels + count, rows.image.pixels.begin(),
                       [](const GpuPixel& p) { return glm::vec3(p); });
        rows.classes.resize(count);
        std::transform(band.classes, band.classes + count, rows.classes.begin(),
                       [](const GpuPixelClass& c) { return PixelClass{c.x, c.y}; });
        rows.depth.resize(aov ? count : 0);
        rows.normals.resize(aov ? count : 0);
        for (std::size_t i = 0; aov && i < count; ++i) {
            const bool background = band.classes[i].x == PixelClass::kBackground;
            rows.depth[i] = background ? std::numeric_limits<float>::infinity() : float(double(band.aovs[i].w) * scale);
            rows.normals[i] = glm::vec3(band.aovs[i]);
        }
        consume(band.firstRow, rows);
    });
    return result;
}

GpuRenderResult GpuRenderer::renderLectureDemoCeiling(const Scene& scene) {
    if (!isLectureDemoScene(scene)) {
        throw std::invalid_argument("the lecture demo's hand-written kernel renders only that scene");
    }
    return renderEncoded(scene, Precision::F32, Kernel::LectureDemoCeiling);
}

GpuRenderResult GpuRenderer::renderEncoded(const Scene& scene, Precision precision, Kernel kernel) {
    GpuRenderResult result;
    result.precision = precision;
    result.encoded = Rgb8Image{scene.image.width, scene.image.height, {}};
    result.encoded.bytes.reserve(std::size_t(scene.image.width) * scene.image.height * 3);
    const GpuRenderResult streamed = encodedRows(scene, precision, kernel, [&](std::uint32_t, auto rgbRows) {
        result.encoded.bytes.insert(result.encoded.bytes.end(), rgbRows.begin(), rgbRows.end());
    });
    result.timing = streamed.timing;
    result.usedBvh = streamed.usedBvh;
    return result;
}

GpuRenderResult GpuRenderer::renderEncodedRows(const Scene& scene, Precision requested, const RowConsumer& consume) {
    return encodedRows(scene, resolve(scene, requested), Kernel::Renderer, consume);
}

GpuRenderResult GpuRenderer::encodedRows(const Scene& scene, Precision precision, Kernel kernel,
                                         const RowConsumer& consume) {
    GpuRenderResult result;
    result.precision = precision;
    std::vector<std::uint8_t> rgb;
    renderBands(scene, precision, GpuOutput::Encoded8, Acceleration::Auto, kernel, result, [&](const Band& band) {
        const std::size_t count = std::size_t(band.rows) * scene.image.width;
        rgb.resize(count * 3);
        for (std::size_t i = 0; i < count; ++i) {
            std::memcpy(&rgb[3 * i], &band.encoded[i], 3);  // RGBA8, R in the lowest byte: drop A
        }
        consume(band.firstRow, rgb);
    });
    return result;
}

namespace {

template <typename Real>
GpuPixelTrace unpackTrace(const Scene& scene, const std::byte* bytes, bool cameraRelative, double scale) {
    gpu::GpuTraceHeader<Real> header;
    std::memcpy(&header, bytes, sizeof header);
    if (header.result.x != 1) {
        throw std::runtime_error("internal error: the trace dispatch wrote nothing");
    }
    const glm::dvec3 eye = cameraRelative ? makePixelSheet(scene.camera, sheetAspect(scene)).origin : glm::dvec3(0);
    const auto world = [&](const gpu::RealVec4<Real>& p) { return eye + scale * glm::dvec3(p); };
    // The shader's NO_HIT is REAL_MAX: 1e300 in f64, FLT_MAX in f32.
    const double miss = std::is_same_v<Real, double> ? 1e299 : 1e38;
    const auto distance = [&](Real t) {
        return double(t) >= miss ? std::numeric_limits<double>::infinity() : double(t) * scale;
    };
    GpuPixelTrace trace;
    trace.cameraRelative = cameraRelative;
    trace.scale = scale;
    trace.rayOrigin = world(header.rayOrigin);
    trace.rayDirection = glm::dvec3(header.rayDirection);
    trace.node = header.result.y;
    trace.flags = header.result.z;
    trace.t = distance(header.hitPosition.w);
    trace.position = world(header.hitPosition);
    trace.normal = glm::dvec3(header.hitNormal);
    trace.shadowOrigin = world(header.shadowOrigin);
    trace.albedo = glm::vec3(header.albedo);
    trace.sampleColor = glm::vec3(header.sampleColor);
    trace.pixelColor = glm::vec3(header.pixelColor);
    const std::byte* entries = bytes + sizeof header;
    const auto entry = [&](std::size_t i) {
        gpu::GpuTraceEntry<Real> e;
        std::memcpy(&e, entries + i * sizeof e, sizeof e);
        return e;
    };
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        trace.candidates.push_back(distance(entry(i).values.x));
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const gpu::GpuTraceEntry<Real> e = entry(scene.nodes.size() + i);
        trace.lights.push_back(GpuTraceLight{e.status.x, double(e.values.x), double(e.values.y) * scale * scale,
                                             double(e.values.z) * scale, glm::vec3(e.color)});
    }
    return trace;
}

template <typename Real>
std::vector<std::byte> traceRequest(const Scene& scene, std::uint32_t x, std::uint32_t y, std::uint32_t sample) {
    std::vector<std::byte> bytes(sizeof(gpu::GpuTraceHeader<Real>) +
                                 (scene.nodes.size() + scene.lights.size()) * sizeof(gpu::GpuTraceEntry<Real>));
    const glm::uvec4 request(x, y, sample, 0);
    std::memcpy(bytes.data(), &request, sizeof request);
    return bytes;
}

}  // namespace

GpuPixelTrace GpuRenderer::tracePixel(const Scene& scene, Precision requested, std::uint32_t x, std::uint32_t y,
                                      std::uint32_t sample) {
    const Precision precision = resolve(scene, requested);
    const bool f64 = precision == Precision::F64;
    const bool cameraRelative = precision != Precision::F32Naive;
    const double scale = cameraRelative ? gpu::placementScale(scene) : 1.0;
    const std::vector<std::byte> request =
        f64 ? traceRequest<double>(scene, x, y, sample) : traceRequest<float>(scene, x, y, sample);
    GpuPixelTrace trace;
    GpuRenderResult bands;
    const auto unpack = [&](const Band& band) {
        trace = f64 ? unpackTrace<double>(scene, band.trace, cameraRelative, scale)
                    : unpackTrace<float>(scene, band.trace, cameraRelative, scale);
    };
    renderBands(scene, precision, GpuOutput::LinearAndClasses, Acceleration::Auto, Kernel::Renderer, bands, unpack,
                request);
    trace.precision = precision;
    trace.usedBvh = bands.usedBvh;
    return trace;
}

void GpuRenderer::renderBands(const Scene& scene, Precision precision, GpuOutput output, Acceleration acceleration,
                              Kernel kernel, GpuRenderResult& result,
                              const std::function<void(const Band&)>& consume,
                              std::span<const std::byte> traceRequest) {
    const bool tracing = !traceRequest.empty();
    const bool aov = output == GpuOutput::LinearClassesAndAov && !tracing;
    const bool linear = output != GpuOutput::Encoded8 && !tracing;
    const std::uint32_t outputMode = tracing                                    ? gpu::kOutputTrace
                                     : aov                                      ? gpu::kOutputLinearClassesAndAov
                                     : linear                                   ? gpu::kOutputLinearAndClasses
                                     : scene.image.encoding == Encoding::Srgb ? gpu::kOutput8BitSrgb
                                                                              : gpu::kOutput8BitLinear;
    SceneLayout layout = gpu::chooseSceneLayout(scene, acceleration, context_.selected().hasSubgroupVote);
    const std::optional<Bvh> bvh = layout == SceneLayout::StorageBvh ? std::optional(buildBvh(scene)) : std::nullopt;
    const PackedScene packed = packFor(scene, precision, layout, bvh ? &*bvh : nullptr);
    if (layout == SceneLayout::StorageBvh && packed.bvhNodes.empty()) {
        layout = SceneLayout::Storage;  // no spheres, or a tree deeper than the shader's stack
    }
    const bool smallScene = layout == SceneLayout::Uniform;
    const gpu::ShaderSpecialization specialization = gpu::specializationFor(scene, outputMode);

    const vk::raii::Device& device = context_.device();
    const vk::raii::PhysicalDevice& physicalDevice = context_.physicalDevice();
    const vk::raii::Pipeline& computePipeline = pipeline({kernel, precision, layout, specialization});
    const SceneBindings& sceneBindings = bindings(layout);
    const std::uint32_t width = scene.image.width;
    const std::uint32_t height = scene.image.height;

    // Large images render in bands of rows so the pixel buffer stays within the device's limit.
    const vk::DeviceSize rowBytes = vk::DeviceSize{width} * sizeof(GpuPixel);
    const vk::DeviceSize bandBytes =
        std::min<vk::DeviceSize>(physicalDevice.getProperties().limits.maxStorageBufferRange, maxBandBytes_);
    const std::uint32_t rowsPerBand = std::uint32_t(std::clamp<vk::DeviceSize>(bandBytes / rowBytes, 1, height));
    const std::size_t bandPixels = std::size_t(rowsPerBand) * width;

    const vk::BufferUsageFlags storage = vk::BufferUsageFlagBits::eStorageBuffer;
    const vk::BufferUsageFlags sceneUsage = smallScene ? vk::BufferUsageFlagBits::eUniformBuffer : storage;
    HostVisibleBuffer frameBuffer(device, physicalDevice, packed.frame.size(), sceneUsage);
    HostVisibleBuffer nodeBuffer(device, physicalDevice, packed.nodes.size(), sceneUsage);
    HostVisibleBuffer lightBuffer(device, physicalDevice, packed.lights.size(), sceneUsage);
    // Only the output mode's buffers get their full size; the others are bound but never written.
    HostVisibleBuffer pixelBuffer(device, physicalDevice, linear ? bandPixels * sizeof(GpuPixel) : 0, storage);
    HostVisibleBuffer classBuffer(device, physicalDevice, linear ? bandPixels * sizeof(GpuPixelClass) : 0, storage);
    HostVisibleBuffer encodedBuffer(device, physicalDevice,
                                    linear || tracing ? 0 : bandPixels * sizeof(gpu::GpuEncodedPixel), storage);
    HostVisibleBuffer aovBuffer(device, physicalDevice, aov ? bandPixels * sizeof(gpu::GpuAovPixel) : 0, storage);
    HostVisibleBuffer traceBuffer(device, physicalDevice, traceRequest.size(), storage);
    if (tracing) {
        traceBuffer.upload(traceRequest);
    }
    HostVisibleBuffer bvhBuffer(device, physicalDevice, packed.bvhNodes.size(), storage);
    HostVisibleBuffer primitiveBuffer(device, physicalDevice, packed.primitives.size(), storage);
    frameBuffer.upload(std::span(packed.frame));
    nodeBuffer.upload(std::span(packed.nodes));
    lightBuffer.upload(std::span(packed.lights));
    bvhBuffer.upload(std::span(packed.bvhNodes));
    primitiveBuffer.upload(std::span(packed.primitives));

    const std::span<const std::uint32_t> setBindings = bindingsOf(smallScene);
    const std::array<vk::DescriptorPoolSize, 2> poolSizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, std::uint32_t(setBindings.size())),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, std::uint32_t(setBindings.size()))};
    vk::raii::DescriptorPool pool(
        device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSizes));
    const vk::DescriptorSetLayout layouts[] = {*sceneBindings.setLayout};
    vk::raii::DescriptorSets sets(device, vk::DescriptorSetAllocateInfo(*pool, layouts));
    const vk::raii::DescriptorSet& set = sets[0];
    const std::array<const HostVisibleBuffer*, kAllBindings.size()> buffers = {
        &frameBuffer, &nodeBuffer, &lightBuffer, &pixelBuffer, &classBuffer,
        &encodedBuffer, &aovBuffer, &traceBuffer, &bvhBuffer, &primitiveBuffer};
    for (std::size_t i = 0; i < setBindings.size(); ++i) {
        const vk::DescriptorBufferInfo info(*buffers[i]->buffer(), 0, buffers[i]->size());
        device.updateDescriptorSets(
            vk::WriteDescriptorSet(*set, setBindings[i], 0, descriptorType(setBindings[i], smallScene), nullptr, info),
            nullptr);
    }

    vk::raii::CommandBuffers commandBuffers(
        device, vk::CommandBufferAllocateInfo(*commandPool_, vk::CommandBufferLevel::ePrimary, 1));
    const vk::raii::CommandBuffer& commands = commandBuffers[0];
    vk::raii::Fence done(device, vk::FenceCreateInfo());
    // Destroyed first when a hang unwinds this scope: the hung dispatch may still be using the
    // objects above, so they are leaked with the device instead (VulkanContext::abandoned()).
    const LeakIfAbandoned leakIfAbandoned{context_, [&] {
        for (HostVisibleBuffer* buffer : {&frameBuffer, &nodeBuffer, &lightBuffer, &pixelBuffer, &classBuffer,
                                          &encodedBuffer, &aovBuffer, &traceBuffer, &bvhBuffer, &primitiveBuffer}) {
            buffer->abandon();
        }
        sets[0].release();
        pool.release();
        commandBuffers[0].release();
        done.release();
    }};

    // Records, submits and waits for one dispatch; returns its duration in milliseconds.
    const auto runDispatch = [&](GpuBand band, std::uint32_t groupsX, std::uint32_t groupsY, bool timed) {
        const bool useTimestamps = timed && *timestamps_;
        commands.reset();
        commands.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
        if (useTimestamps) {
            commands.resetQueryPool(*timestamps_, 0, 2);
            commands.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *timestamps_, 0);
        }
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *computePipeline);
        commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *sceneBindings.pipelineLayout, 0, *set, nullptr);
        commands.pushConstants<GpuBand>(*sceneBindings.pipelineLayout, vk::ShaderStageFlagBits::eCompute, 0, band);
        commands.dispatch(groupsX, groupsY, 1);
        if (useTimestamps) {
            commands.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *timestamps_, 1);
        }
        // The shader's writes must be visible to the host's reads of the mapped buffers.
        const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
        commands.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {},
                                 toHost, nullptr, nullptr);
        commands.end();

        const auto start = std::chrono::steady_clock::now();
        const std::uint64_t samples = std::uint64_t(groupsX) * groupsY * kWorkgroupSize * kWorkgroupSize *
                                      scene.image.samplesPerPixel;
        context_.submitAndWait(commands, done, dispatchTimeout(scene, samples));  // throws VulkanError
        device.resetFences(*done);
        const double wallMilliseconds = millisecondsSince(start);
        if (!useTimestamps) {
            return wallMilliseconds;
        }
        const auto [result, ticks] = timestamps_.getResults<std::uint64_t>(
            0, 2, 2 * sizeof(std::uint64_t), sizeof(std::uint64_t),
            vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
        return double((ticks[1] - ticks[0]) & timestampMask_) * nanosecondsPerTick_ * 1e-6;
    };

    result.usedBvh = layout == SceneLayout::StorageBvh;
    GpuTiming& timing = result.timing;
    timing.fromTimestamps = static_cast<bool>(*timestamps_);
    if (tracing) {
        // One invocation does the work; the pixel is in the request, not in the dispatch.
        timing.renderMilliseconds = runDispatch(GpuBand{0, 1}, 1, 1, false);
        consume(Band{0, 0, nullptr, nullptr, nullptr, nullptr, traceBuffer.data()});
        return;
    }
    // Warm-up: one workgroup, so the driver's shader compile (lavapipe JITs at the first
    // dispatch) is not counted as render time.
    timing.firstDispatchMilliseconds = runDispatch(GpuBand{0, std::min(rowsPerBand, kWorkgroupSize)}, 1, 1, false);

    for (std::uint32_t firstRow = 0; firstRow < height; firstRow += rowsPerBand) {
        const std::uint32_t rows = std::min(rowsPerBand, height - firstRow);
        timing.renderMilliseconds += runDispatch(GpuBand{firstRow, rows}, groupsFor(width), groupsFor(rows), true);
        consume(Band{firstRow, rows, reinterpret_cast<const GpuPixel*>(pixelBuffer.data()),
                     reinterpret_cast<const GpuPixelClass*>(classBuffer.data()),
                     reinterpret_cast<const gpu::GpuEncodedPixel*>(encodedBuffer.data()),
                     reinterpret_cast<const gpu::GpuAovPixel*>(aovBuffer.data()), traceBuffer.data()});
    }
}

}  // namespace hexray
