#include "vulkan/texel_buffer.h"

namespace hexray::inline vulkan {

TexelBuffer::TexelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                         vk::DeviceSize size, vk::Format format, vk::BufferUsageFlags alsoUsedAs)
    : buffer_(device, physicalDevice, size, vk::BufferUsageFlagBits::eUniformTexelBuffer | alsoUsedAs),
      view_(device, vk::BufferViewCreateInfo({}, *buffer_.buffer(), format, 0, VK_WHOLE_SIZE)) {}

TexelBuffer::TexelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                         std::span<const std::byte> bytes, vk::DeviceSize alignment, vk::Format format)
    : buffer_(device, physicalDevice, bytes, alignment, vk::BufferUsageFlagBits::eUniformTexelBuffer),
      view_(device, vk::BufferViewCreateInfo({}, *buffer_.buffer(), format, 0, VK_WHOLE_SIZE)) {}

void TexelBuffer::bind(const vk::raii::Device& device, const vk::raii::DescriptorSet& set, std::uint32_t binding,
                       vk::DescriptorType type) const {
    if (type == vk::DescriptorType::eUniformTexelBuffer) {
        const vk::BufferView view = *view_;
        device.updateDescriptorSets(vk::WriteDescriptorSet(*set, binding, 0, 1, type, nullptr, nullptr, &view),
                                    nullptr);
        return;
    }
    const vk::DescriptorBufferInfo info(*buffer_.buffer(), 0, buffer_.size());
    device.updateDescriptorSets(vk::WriteDescriptorSet(*set, binding, 0, type, nullptr, info), nullptr);
}

void TexelBuffer::abandon() {
    view_.release();
    buffer_.abandon();
}

}  // namespace hexray::vulkan
