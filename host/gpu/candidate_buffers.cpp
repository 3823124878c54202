#include "gpu/candidate_buffers.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

#include "util/parallel_parts.h"
#include "util/uninitialized_vector.h"

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

TexelBuffer CandidateBuffers::listBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                         std::span<const std::byte> list, vk::DeviceSize importAlignment) {
    // UninitializedVector's storage spans whole pages: enough for an alignment up to a page.
    const bool importable = importAlignment != 0 && list.size() >= importAlignment &&
                            reinterpret_cast<std::uintptr_t>(list.data()) % importAlignment == 0 &&
                            importAlignment <= DefaultInitAllocator<std::byte>::kPageBytes;
    if (importable) {
        return TexelBuffer(device, physicalDevice, list, importAlignment, vk::Format::eR32Uint);
    }
    return texelBuffer(device, physicalDevice, {list}, vk::Format::eR32Uint);
}

CandidateBuffers::CandidateBuffers(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                   std::shared_ptr<const CandidateLists> lists, const BufferContents& sphereRecords,
                                   vk::DeviceSize importAlignment)
    : lists_(std::move(lists)),
      buffers_{texelBuffer(device, physicalDevice,
                           {lists_ ? std::as_bytes(std::span(&lists_->cameraAxes, 1)) : std::span<const std::byte>(),
                            lists_ ? bytesOf(lists_->grids) : std::span<const std::byte>()},
                           vk::Format::eR32G32B32A32Uint),
               listBuffer(device, physicalDevice, lists_ ? bytesOf(lists_->cellStarts) : std::span<const std::byte>(),
                          importAlignment),
               listBuffer(device, physicalDevice, lists_ ? bytesOf(lists_->entries) : std::span<const std::byte>(),
                          importAlignment),
               texelBuffer(device, physicalDevice, sphereRecords, vk::Format::eR32G32B32A32Uint)} {}

void CandidateBuffers::write(const vk::raii::Device& device, const vk::raii::DescriptorSet& set) const {
    for (std::size_t i = 0; i < kBindings.size(); ++i) {
        buffers_[i].bind(device, set, kBindings[i]);
    }
}

std::span<const std::byte> CandidateBuffers::contents(std::uint32_t binding) const {
    const auto at = std::find(kBindings.begin(), kBindings.end(), binding) - kBindings.begin();
    const HostVisibleBuffer& buffer = buffers_.at(std::size_t(at)).buffer();
    return {buffer.data(), buffer.size()};
}

void CandidateBuffers::abandon() {
    for (TexelBuffer& texels : buffers_) {
        texels.abandon();
    }
    // A hung device may still read what its buffers imported: the lists are never freed (held
    // from a static, so a leak checker sees them reachable).
    if (lists_) {
        static std::mutex mutex;
        static auto* const kept = new std::vector<std::shared_ptr<const CandidateLists>>;
        const std::lock_guard lock(mutex);
        kept->push_back(lists_);
    }
}

}  // namespace hexray::gpu
