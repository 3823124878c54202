#pragma once
// A buffer the host maps directly (uniform or storage): how hexray uploads the scene and reads
// pixels back.
// On lavapipe all memory is host-visible; on a discrete GPU this is slower than a staging copy
// but correct, and hexray's buffers are small next to its render time.

#include <cstddef>
#include <cstring>
#include <span>

#include <vulkan/vulkan_raii.hpp>

namespace hexray::inline vulkan {

class HostVisibleBuffer {
public:
    // `size` is raised to at least 16 bytes so an empty array (or an unused output) still binds.
    HostVisibleBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                      vk::DeviceSize size, vk::BufferUsageFlags usage);

    // A buffer over `bytes`, the host's own memory, imported (VK_EXT_external_memory_host, enabled
    // on `device`): no copy. `bytes` must start at a multiple of `alignment` and the memory go on
    // to the next multiple past its end; the caller keeps it alive and unchanged while the device
    // may read it.
    HostVisibleBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                      std::span<const std::byte> bytes, vk::DeviceSize alignment, vk::BufferUsageFlags usage);

    const vk::raii::Buffer& buffer() const { return buffer_; }
    vk::DeviceSize size() const { return size_; }
    std::byte* data() const { return mapped_; }

    void upload(std::span<const std::byte> bytes) {
        if (!bytes.empty()) {  // an empty span may have a null data(), which memcpy must not get
            std::memcpy(mapped_, bytes.data(), bytes.size());
        }
    }

    // Leaves the buffer and its memory (still mapped) to a device that hung: see
    // VulkanContext::abandoned().
    void abandon() {
        buffer_.release();
        memory_.release();
    }

private:
    vk::DeviceSize size_;
    vk::raii::DeviceMemory memory_;  // declared first so the buffer is destroyed before it
    vk::raii::Buffer buffer_;
    std::byte* mapped_ = nullptr;  // stays mapped for the buffer's life; unmapped with the memory
};

}  // namespace hexray::vulkan
