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
        const bool large = size_ >= (1u << 20);
        const std::string amount = large ? std::to_string((size_ + (1u << 20) - 1) >> 20) + " MiB"
                                         : std::to_string((size_ + 1023) >> 10) + " KiB";
        throw classify(error, "allocating a " + amount + " buffer");
    }
}

}  // namespace hexray::vulkan
