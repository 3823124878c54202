#pragma once
// A host-visible buffer with a view of its whole size in one texel format: bound as a uniform
// texel buffer (or, where asked for at creation, as a uniform buffer of the same bytes).

#include <cstdint>

#include <vulkan/vulkan_raii.hpp>

#include "vulkan/host_visible_buffer.h"

namespace hexray::inline vulkan {

class TexelBuffer {
public:
    TexelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice, vk::DeviceSize size,
                vk::Format format, vk::BufferUsageFlags alsoUsedAs = {});
    // Over the host's own memory, imported: see HostVisibleBuffer's importing constructor.
    TexelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                std::span<const std::byte> bytes, vk::DeviceSize alignment, vk::Format format);

    HostVisibleBuffer& buffer() { return buffer_; }
    const HostVisibleBuffer& buffer() const { return buffer_; }

    // Writes this buffer into `binding` of `set` as `type`: eUniformTexelBuffer (the view) or
    // eUniformBuffer (needs alsoUsedAs).
    void bind(const vk::raii::Device& device, const vk::raii::DescriptorSet& set, std::uint32_t binding,
              vk::DescriptorType type = vk::DescriptorType::eUniformTexelBuffer) const;

    // See HostVisibleBuffer::abandon.
    void abandon();

private:
    HostVisibleBuffer buffer_;
    vk::raii::BufferView view_;
};

}  // namespace hexray::vulkan
