#pragma once
// The candidate lists on the device (shaders/candidates.glsl): four uniform texel buffers, bound
// at the CANDIDATE_* bindings. Scenes without lists bind one-texel stand-ins.

#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>

#include <vulkan/vulkan_raii.hpp>

#include "accel/candidate_lists.h"
#include "gpu/buffer_contents.h"
#include "vulkan/texel_buffer.h"

namespace hexray::inline gpu {

class CandidateBuffers {
public:
    static constexpr std::array<std::uint32_t, 4> kBindings = {gpu::CANDIDATE_GRID_BINDING, gpu::CANDIDATE_CELL_BINDING,
                                                               gpu::CANDIDATE_ENTRY_BINDING,
                                                               gpu::CANDIDATE_SPHERE_BINDING};
    static bool isCandidateBinding(std::uint32_t binding);

    // Uploads `lists` (may be null) and the spheres' records (gpu_scene.h's packCandidateSpheresInto).
    // With an `importAlignment` (VulkanContext's DeviceInfo::hostImportAlignment) the cell starts
    // and the entries are not copied: the buffers import them, and hold the lists while they live.
    CandidateBuffers(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                     std::shared_ptr<const CandidateLists> lists, const BufferContents& sphereRecords,
                     vk::DeviceSize importAlignment = 0);

    void write(const vk::raii::Device& device, const vk::raii::DescriptorSet& set) const;

    // What the buffer bound at `binding` (one of kBindings) holds, where the host sees it.
    std::span<const std::byte> contents(std::uint32_t binding) const;

    // See HostVisibleBuffer::abandon.
    void abandon();

private:
    // A buffer of `pieces` one after the other (no joined copy of them on the host).
    static TexelBuffer texelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                   std::initializer_list<std::span<const std::byte>> pieces, vk::Format format);

    static TexelBuffer texelBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                   const BufferContents& contents, vk::Format format);

    // A list of words: imported where it can be, else copied.
    static TexelBuffer listBuffer(const vk::raii::Device& device, const vk::raii::PhysicalDevice& physicalDevice,
                                  std::span<const std::byte> list, vk::DeviceSize importAlignment);

    std::shared_ptr<const CandidateLists> lists_;  // declared first: outlives the buffers that import it
    std::array<TexelBuffer, 4> buffers_;           // in kBindings' order
};

}  // namespace hexray::gpu
