#include "gpu/candidate_buffers.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "util/parallel_parts.h"

namespace hexray::inline gpu {
namespace {

template <typename Values>
std::span<const std::byte> bytesOf(const Values& values) {
    return std::as_bytes(std::span(values));
}

// The lists are copied on every core, in parts of at least this many bytes: most of a large copy's
// time goes to the fresh buffer's first touch, which the cores share.
constexpr std::size_t kBytesPerCopyPart = std::size_t{4} << 20;

void copyAcrossCores(std::byte* to, std::span<const std::byte> from) {
    runAcrossCores(from.size(), kBytesPerCopyPart, [&](std::size_t first, std::size_t end) {
        if (end > first) {  // an empty span may have a null data(), which memcpy must not get
            std::memcpy(to + first, from.data() + first, end - first);
        }
    });
}

}  // namespace

bool CandidateBuffers::isCandidateBinding(std::uint32_t binding) {
    return std::find(kBindings.begin(), kBindings.end(), binding) != kBindings.end();
}

TexelBuffer CandidateBuffers::texelBuffer(const vk::raii::Device& device,
                                          const vk::raii::PhysicalDevice& physicalDevice,
                                          std::initializer_list<std::span<const std::byte>> pieces, vk::Format format) {
    std::size_t size = 0;
    for (const std::span<const std::byte> piece : pieces) {
        size += piece.size();
    }
    TexelBuffer texels(device, physicalDevice, size, format);
    std::size_t offset = 0;
    for (const std::span<const std::byte> piece : pieces) {
        copyAcrossCores(texels.buffer().data() + offset, piece);
        offset += piece.size();
    }
    return texels;
}

TexelBuffer CandidateBuffers::texelBuffer(const vk::raii::Device& device,
                                          const vk::raii::PhysicalDevice& physicalDevice,
                                          const BufferContents& contents, vk::Format format) {
    TexelBuffer texels(device, physicalDevice, contents.size(), format);
    contents.writeTo(texels.buffer().data());
    return texels;
}

CandidateBuffers::CandidateBuffers(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                   const CandidateLists* lists, const BufferContents& sphereRecords)
    : buffers_{texelBuffer(device, physicalDevice,
                           {lists ? std::as_bytes(std::span(&lists->cameraAxes, 1)) : std::span<const std::byte>(),
                            lists ? bytesOf(lists->grids) : std::span<const std::byte>()},
                           vk::Format::eR32G32B32A32Uint),
               texelBuffer(device, physicalDevice, {lists ? bytesOf(lists->cellStarts) : std::span<const std::byte>()},
                           vk::Format::eR32Uint),
               texelBuffer(device, physicalDevice, {lists ? bytesOf(lists->entries) : std::span<const std::byte>()},
                           vk::Format::eR32Uint),
               texelBuffer(device, physicalDevice, sphereRecords, vk::Format::eR32G32B32A32Uint)} {}

void CandidateBuffers::write(const vk::raii::Device& device, const vk::raii::DescriptorSet& set) const {
    for (std::size_t i = 0; i < kBindings.size(); ++i) {
        buffers_[i].bind(device, set, kBindings[i]);
    }
}

void CandidateBuffers::abandon() {
    for (TexelBuffer& texels : buffers_) {
        texels.abandon();
    }
}

}  // namespace hexray::gpu
