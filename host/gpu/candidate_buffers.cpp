#include "gpu/candidate_buffers.h"

#include <algorithm>
#include <vector>

namespace hexray {
namespace {

template <typename T>
std::span<const std::byte> bytesOf(const std::vector<T>& values) {
    return std::as_bytes(std::span(values));
}

}  // namespace

bool CandidateBuffers::isCandidateBinding(std::uint32_t binding) {
    return std::find(kBindings.begin(), kBindings.end(), binding) != kBindings.end();
}

CandidateBuffers::TexelBuffer CandidateBuffers::texelBuffer(const vk::raii::Device& device,
                                                            const vk::raii::PhysicalDevice& physicalDevice,
                                                            std::span<const std::byte> bytes, vk::Format format) {
    HostVisibleBuffer buffer(device, physicalDevice, bytes.size(), vk::BufferUsageFlagBits::eUniformTexelBuffer);
    buffer.upload(bytes);
    vk::raii::BufferView view(device, vk::BufferViewCreateInfo({}, *buffer.buffer(), format, 0, VK_WHOLE_SIZE));
    return TexelBuffer{std::move(buffer), std::move(view)};
}

CandidateBuffers::CandidateBuffers(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                   const CandidateLists* lists, std::span<const std::byte> sphereRecords)
    : buffers_{
          texelBuffer(device, physicalDevice, lists ? std::span<const std::byte>(lists->gridBytes()) : std::span<const std::byte>(),
                      vk::Format::eR32G32B32A32Uint),
          texelBuffer(device, physicalDevice, lists ? bytesOf(lists->cellStarts) : std::span<const std::byte>(),
                      vk::Format::eR32Uint),
          texelBuffer(device, physicalDevice, lists ? bytesOf(lists->entries) : std::span<const std::byte>(),
                      vk::Format::eR32Uint),
          texelBuffer(device, physicalDevice, sphereRecords, vk::Format::eR32G32B32A32Uint)} {}

void CandidateBuffers::write(const vk::raii::Device& device, const vk::raii::DescriptorSet& set) const {
    for (std::size_t i = 0; i < kBindings.size(); ++i) {
        const vk::BufferView view = *buffers_[i].view;
        device.updateDescriptorSets(
            vk::WriteDescriptorSet(*set, kBindings[i], 0, 1, vk::DescriptorType::eUniformTexelBuffer, nullptr, nullptr,
                                   &view),
            nullptr);
    }
}

void CandidateBuffers::abandon() {
    for (TexelBuffer& texels : buffers_) {
        texels.view.release();
        texels.buffer.abandon();
    }
}

}  // namespace hexray
