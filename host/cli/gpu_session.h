#pragma once
// The Vulkan instance, device and renderer that every scene of one command shares (and with the
// renderer its kernel compiler, which caches generated kernels in memory and on disk, and its
// pipelines), made on first use: rendering twenty scenes starts Vulkan once.

#include <optional>

#include "cli/commands.h"
#include "gpu/gpu_renderer.h"
#include "vulkan/vulkan_context.h"

namespace hexray::cli {

class GpuSession {
public:
    GpuSession(const VulkanOptions& options, ValidationLog& log);

    // Throws VulkanError when Vulkan cannot be set up, and, once failed() was called, that
    // failure again: a device lost or hung mid-render is not used again.
    const VulkanContext& context();
    // For the 8-bit image: the renderer's own (largest) bands.
    GpuRenderer& renderer();
    // For rows that come back as floats (OpenEXR, the AOVs): bands of at most kBandBytes, so
    // memory grows with the image's width only.
    GpuRenderer& linearRenderer();

    void failed(const VulkanError& error);
    // Whether Vulkan was set up (or failed to be) already.
    bool started() const { return context_ || failure_; }

    // For --json: the device in use and how long setting Vulkan up took; none before it was set
    // up, or when that failed.
    std::optional<DeviceInfo> device() const;
    std::optional<double> startupMilliseconds() const { return startupMilliseconds_; }

private:
    void start();

    VulkanOptions options_;
    ValidationLog& log_;
    std::optional<VulkanError> failure_;
    std::optional<double> startupMilliseconds_;
    std::optional<VulkanContext> context_;  // declared before the renderers, which it outlives
    std::optional<GpuRenderer> renderer_;
    std::optional<GpuRenderer> linearRenderer_;
};

}  // namespace hexray::cli
