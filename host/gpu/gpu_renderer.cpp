#include "gpu/gpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <span>

#include "gpu/gpu_layout.h"
#include "gpu/gpu_scene.h"
#include "vulkan/host_visible_buffer.h"

namespace {
// SPIR-V generated from shaders/render.comp at build time, one array per precision variant.
#include "kRenderF32NaiveSpv.h"
#include "kRenderF32Spv.h"
#include "kRenderF64Spv.h"
}  // namespace

namespace hexray {
namespace {

using gpu::GpuBand;
using gpu::GpuPixel;
using gpu::GpuPixelClass;
using gpu::kWorkgroupSize;

constexpr std::array<std::uint32_t, 5> kBindings = {gpu::kFrameBinding, gpu::kNodeBinding, gpu::kLightBinding,
                                                    gpu::kPixelBinding, gpu::kClassBinding};

std::span<const std::uint32_t> spirvFor(Precision precision) {
    switch (precision) {
        case Precision::F32Naive: return kRenderF32NaiveSpv;
        case Precision::F64: return kRenderF64Spv;
        default: return kRenderF32Spv;
    }
}

vk::raii::DescriptorSetLayout createSetLayout(const vk::raii::Device& device) {
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding : kBindings) {
        bindings.emplace_back(binding, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute);
    }
    return vk::raii::DescriptorSetLayout(device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

vk::raii::PipelineLayout createPipelineLayout(const vk::raii::Device& device,
                                              const vk::raii::DescriptorSetLayout& setLayout) {
    const vk::PushConstantRange band(vk::ShaderStageFlagBits::eCompute, 0, sizeof(GpuBand));
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    return vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo({}, layouts, band));
}

vk::raii::Pipeline createPipeline(const vk::raii::Device& device, const vk::raii::PipelineLayout& layout,
                                  std::span<const std::uint32_t> spirv) {
    const vk::raii::ShaderModule module(device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
    // Local size x and y are specialization constants 0 and 1, so the host's value is the only one.
    const std::array<vk::SpecializationMapEntry, 2> entries = {
        vk::SpecializationMapEntry(0, 0, sizeof(std::uint32_t)),
        vk::SpecializationMapEntry(1, sizeof(std::uint32_t), sizeof(std::uint32_t))};
    const std::array<std::uint32_t, 2> localSize = {kWorkgroupSize, kWorkgroupSize};
    const vk::SpecializationInfo specialization(entries, vk::ArrayProxyNoTemporaries<const std::uint32_t>(localSize));
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main",
                                                  &specialization);
    return vk::raii::Pipeline(device, nullptr, vk::ComputePipelineCreateInfo({}, stage, *layout));
}

// The scene in the chosen variant's layout, as the bytes the buffers receive.
struct PackedScene {
    std::vector<std::byte> frame;
    std::vector<std::byte> nodes;
    std::vector<std::byte> lights;
};

template <typename T>
std::vector<std::byte> bytesOf(std::span<const T> values) {
    const auto bytes = std::as_bytes(values);
    return {bytes.begin(), bytes.end()};
}

template <typename Real>
PackedScene packBytes(const Scene& scene, gpu::Placement placement) {
    const gpu::GpuScene<Real> packed = gpu::packScene<Real>(scene, placement);
    return {bytesOf(std::span(&packed.frame, 1)), bytesOf(std::span(packed.nodes)), bytesOf(std::span(packed.lights))};
}

PackedScene packFor(const Scene& scene, Precision precision) {
    switch (precision) {
        case Precision::F64: return packBytes<double>(scene, gpu::Placement::CameraRelative);
        case Precision::F32Naive: return packBytes<float>(scene, gpu::Placement::World);
        default: return packBytes<float>(scene, gpu::Placement::CameraRelative);
    }
}

std::uint32_t groupsFor(std::uint32_t count) {
    return (count + kWorkgroupSize - 1) / kWorkgroupSize;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GpuRenderer::GpuRenderer(const VulkanContext& context, std::uint64_t maxBandBytes)
    : context_(context),
      maxBandBytes_(maxBandBytes),
      setLayout_(createSetLayout(context.device())),
      pipelineLayout_(createPipelineLayout(context.device(), setLayout_)),
      commandPool_(context.device(),
                   vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, context.queueFamily())),
      timestamps_(nullptr) {
    const auto families = context.physicalDevice().getQueueFamilyProperties();
    const std::uint32_t validBits = families[context.queueFamily()].timestampValidBits;
    if (validBits > 0) {
        timestamps_ = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2));
        nanosecondsPerTick_ = context.physicalDevice().getProperties().limits.timestampPeriod;
        timestampMask_ = validBits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << validBits) - 1;
    }
}

Precision GpuRenderer::resolve(const Scene& scene, Precision requested) const {
    const bool hasFloat64 = context_.selected().hasFloat64;
    if (requested == Precision::Auto) {
        return choosePrecision(scene, hasFloat64);
    }
    if (requested == Precision::F64 && !hasFloat64) {
        throw VulkanError("--precision f64 needs shaderFloat64, which " + context_.selected().name +
                          " does not have; use --precision f32");
    }
    return requested;
}

const vk::raii::Pipeline& GpuRenderer::pipeline(Precision precision) {
    std::optional<vk::raii::Pipeline>& slot = pipelines_[std::size_t(precision)];
    if (!slot) {
        slot.emplace(createPipeline(context_.device(), pipelineLayout_, spirvFor(precision)));
    }
    return *slot;
}

GpuRenderResult GpuRenderer::render(const Scene& scene, Precision requested) {
    const Precision precision = resolve(scene, requested);
    const vk::raii::Device& device = context_.device();
    const vk::raii::PhysicalDevice& physicalDevice = context_.physicalDevice();
    const vk::raii::Pipeline& computePipeline = pipeline(precision);
    const std::uint32_t width = scene.image.width;
    const std::uint32_t height = scene.image.height;

    // Large images render in bands of rows so the pixel buffer stays within the device's limit.
    const vk::DeviceSize rowBytes = vk::DeviceSize{width} * sizeof(GpuPixel);
    const vk::DeviceSize bandBytes =
        std::min<vk::DeviceSize>(physicalDevice.getProperties().limits.maxStorageBufferRange, maxBandBytes_);
    const std::uint32_t rowsPerBand = std::uint32_t(std::clamp<vk::DeviceSize>(bandBytes / rowBytes, 1, height));
    const std::size_t bandPixels = std::size_t(rowsPerBand) * width;

    const PackedScene packed = packFor(scene, precision);
    const vk::BufferUsageFlags usage = vk::BufferUsageFlagBits::eStorageBuffer;
    HostVisibleBuffer frameBuffer(device, physicalDevice, packed.frame.size(), usage);
    HostVisibleBuffer nodeBuffer(device, physicalDevice, packed.nodes.size(), usage);
    HostVisibleBuffer lightBuffer(device, physicalDevice, packed.lights.size(), usage);
    HostVisibleBuffer pixelBuffer(device, physicalDevice, bandPixels * sizeof(GpuPixel), usage);
    HostVisibleBuffer classBuffer(device, physicalDevice, bandPixels * sizeof(GpuPixelClass), usage);
    frameBuffer.upload(std::span(packed.frame));
    nodeBuffer.upload(std::span(packed.nodes));
    lightBuffer.upload(std::span(packed.lights));

    const vk::DescriptorPoolSize poolSize(vk::DescriptorType::eStorageBuffer, std::uint32_t(kBindings.size()));
    const vk::raii::DescriptorPool pool(
        device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSize));
    const vk::DescriptorSetLayout layouts[] = {*setLayout_};
    vk::raii::DescriptorSets sets(device, vk::DescriptorSetAllocateInfo(*pool, layouts));
    const vk::raii::DescriptorSet& set = sets[0];
    const std::array<const HostVisibleBuffer*, 5> buffers = {&frameBuffer, &nodeBuffer, &lightBuffer, &pixelBuffer,
                                                             &classBuffer};
    for (std::size_t i = 0; i < kBindings.size(); ++i) {
        const vk::DescriptorBufferInfo info(*buffers[i]->buffer(), 0, buffers[i]->size());
        device.updateDescriptorSets(vk::WriteDescriptorSet(*set, kBindings[i], 0, vk::DescriptorType::eStorageBuffer,
                                                           nullptr, info),
                                    nullptr);
    }

    vk::raii::CommandBuffers commandBuffers(
        device, vk::CommandBufferAllocateInfo(*commandPool_, vk::CommandBufferLevel::ePrimary, 1));
    const vk::raii::CommandBuffer& commands = commandBuffers[0];
    const vk::raii::Fence done(device, vk::FenceCreateInfo());

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
        commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipelineLayout_, 0, *set, nullptr);
        commands.pushConstants<GpuBand>(*pipelineLayout_, vk::ShaderStageFlagBits::eCompute, 0, band);
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
        context_.queue().submit(vk::SubmitInfo({}, {}, *commands), *done);
        if (device.waitForFences(*done, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess) {
            throw VulkanError("waiting for the render to finish failed");
        }
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

    GpuRenderResult result;
    result.image = Image(width, height);
    result.classes.resize(std::size_t(width) * height);
    result.precision = precision;
    result.timing.fromTimestamps = static_cast<bool>(*timestamps_);
    // Warm-up: one workgroup, so the driver's shader compile (lavapipe JITs at the first
    // dispatch) is not counted as render time.
    result.timing.firstDispatchMilliseconds =
        runDispatch(GpuBand{0, std::min(rowsPerBand, kWorkgroupSize)}, 1, 1, false);

    for (std::uint32_t firstRow = 0; firstRow < height; firstRow += rowsPerBand) {
        const std::uint32_t rows = std::min(rowsPerBand, height - firstRow);
        result.timing.renderMilliseconds += runDispatch(GpuBand{firstRow, rows}, groupsFor(width), groupsFor(rows), true);
        const std::size_t count = std::size_t(rows) * width;
        const std::size_t first = std::size_t(firstRow) * width;
        const auto* pixels = reinterpret_cast<const GpuPixel*>(pixelBuffer.data());
        std::transform(pixels, pixels + count, result.image.pixels.begin() + std::ptrdiff_t(first),
                       [](const GpuPixel& p) { return glm::vec3(p); });
        const auto* classes = reinterpret_cast<const GpuPixelClass*>(classBuffer.data());
        std::transform(classes, classes + count, result.classes.begin() + std::ptrdiff_t(first),
                       [](const GpuPixelClass& c) { return PixelClass{c.x, c.y}; });
    }
    return result;
}

}  // namespace hexray
