#include "cli/gpu_session.h"

#include <chrono>

#include "cli/command_support.h"

namespace hexray::cli {

GpuSession::GpuSession(const VulkanOptions& options, ValidationLog& log) : options_(options), log_(log) {}

void GpuSession::start() {
    if (failure_) {
        throw *failure_;
    }
    if (context_) {
        return;
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        context_.emplace(VulkanContext::Options{options_.validate ? &log_ : nullptr, options_.device});
        startupMilliseconds_ = millisecondsSince(start);
    } catch (const VulkanError& error) {
        failed(error);
        throw;
    } catch (const vk::SystemError& error) {
        failed(classify(error, "setting up Vulkan"));
        throw *failure_;
    }
}

GpuRenderer& GpuSession::renderer() {
    start();
    if (!renderer_) {
        renderer_.emplace(*context_);
    }
    return *renderer_;
}

GpuRenderer& GpuSession::linearRenderer() {
    start();
    if (!linearRenderer_) {
        linearRenderer_.emplace(*context_, kBandBytes);
    }
    return *linearRenderer_;
}

std::optional<DeviceInfo> GpuSession::device() const {
    return context_ ? std::optional<DeviceInfo>(context_->selected()) : std::nullopt;
}

const VulkanContext& GpuSession::context() {
    start();
    return *context_;
}

void GpuSession::failed(const VulkanError& error) {
    failure_ = error;
}

}  // namespace hexray::cli
