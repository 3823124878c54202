#include "vulkan/host_visible_buffer.h"

#include <algorithm>
#include <optional>

#include "vulkan/fault_injection.h"
#include "vulkan/vulkan_context.h"

namespace hexray::inline vulkan {
namespace {

// A memory type that is host-visible and coherent (no flushes needed), cached if possible
// because hexray reads the image back through it.
std::uint32_t hostMemoryType(const vk::raii::PhysicalDevice& physicalDevice, std::uint32_t allowedTypes) {
    const vk::PhysicalDeviceMemoryProperties memory = physicalDevice.getMemoryProperties();
    const vk::MemoryPropertyFlags required =
        vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent;
    std::optional<std::uint32_t> found;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        const vk::MemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
        if (!(allowedTypes & (1u << i)) || (flags & required) != required) {
            continue;
        }
        if (!found || (flags & vk::MemoryPropertyFlagBits::eHostCached)) {
            found = i;
        }
    }
    if (!found) {
        throw VulkanError(VulkanFailure::Unavailable,
                          "the Vulkan device has no host-visible, coherent memory for hexray's buffers");
    }
    return *found;
}

std::string amountOf(vk::DeviceSize size) {
    const bool large = size >= (1u << 20);
    return large ? std::to_string((size + (1u << 20) - 1) >> 20) + " MiB"
                 : std::to_string((size + 1023) >> 10) + " KiB";
}

}  // namespace

HostVisibleBuffer::HostVisibleBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                     vk::DeviceSize size, vk::BufferUsageFlags usage)
    : size_(std::max<vk::DeviceSize>(size, 16)), memory_(nullptr), buffer_(nullptr) {
    try {
        buffer_ = vk::raii::Buffer(device, vk::BufferCreateInfo({}, size_, usage, vk::SharingMode::eExclusive));
        const vk::MemoryRequirements requirements = buffer_.getMemoryRequirements();
        const vk::MemoryAllocateInfo allocation(requirements.size,
                                                hostMemoryType(physicalDevice, requirements.memoryTypeBits));
        if (injected(InjectedFault::OutOfDeviceMemory)) {
            throw vk::OutOfDeviceMemoryError("vkAllocateMemory");
        }
        memory_ = vk::raii::DeviceMemory(device, allocation);
        buffer_.bindMemory(*memory_, 0);
        mapped_ = static_cast<std::byte*>(memory_.mapMemory(0, size_));
    } catch (const vk::SystemError& error) {
        throw classify(error, "allocating a " + amountOf(size_) + " buffer");
    }
}

HostVisibleBuffer::HostVisibleBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                     std::span<const std::byte> bytes, vk::DeviceSize alignment,
                                     vk::BufferUsageFlags usage)
    : size_(bytes.size()), memory_(nullptr), buffer_(nullptr) {
    constexpr auto kHost = vk::ExternalMemoryHandleTypeFlagBits::eHostAllocationEXT;
    void* host = const_cast<std::byte*>(bytes.data());  // the device only reads it
    try {
        const vk::ExternalMemoryBufferCreateInfo external(kHost);
        buffer_ = vk::raii::Buffer(device,
                                   vk::BufferCreateInfo({}, size_, usage, vk::SharingMode::eExclusive, {}, &external));
        const vk::MemoryRequirements requirements = buffer_.getMemoryRequirements();
        const std::uint32_t types = device.getMemoryHostPointerPropertiesEXT(kHost, host).memoryTypeBits;
        const vk::ImportMemoryHostPointerInfoEXT import(kHost, host);
        const vk::DeviceSize whole = (size_ + alignment - 1) / alignment * alignment;
        if (requirements.size > whole) {
            throw VulkanError(VulkanFailure::Unavailable, "the Vulkan device needs more memory for a buffer of " +
                                                              amountOf(size_) + " than the host memory it imports");
        }
        const vk::MemoryAllocateInfo allocation(
            whole, hostMemoryType(physicalDevice, requirements.memoryTypeBits & types), &import);
        memory_ = vk::raii::DeviceMemory(device, allocation);
        buffer_.bindMemory(*memory_, 0);
        mapped_ = static_cast<std::byte*>(host);
    } catch (const vk::SystemError& error) {
        throw classify(error, "importing a " + amountOf(size_) + " buffer");
    }
}

}  // namespace hexray::vulkan
