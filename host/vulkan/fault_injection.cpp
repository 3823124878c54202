#include "vulkan/fault_injection.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hexray::inline vulkan {
namespace {

InjectedFault parse(const char* value) {
    const std::string_view name = value ? value : "";
    if (name.empty())
        return InjectedFault::None;
    if (name == "no-compute-queue")
        return InjectedFault::NoComputeQueue;
    if (name == "no-float64")
        return InjectedFault::NoFloat64;
    if (name == "device-lost")
        return InjectedFault::DeviceLost;
    if (name == "device-hang")
        return InjectedFault::DeviceHang;
    if (name == "out-of-device-memory")
        return InjectedFault::OutOfDeviceMemory;
    if (name == "pipeline-fails-once")
        return InjectedFault::PipelineFailsOnce;
    throw std::invalid_argument("HEXRAY_INJECT_VULKAN_FAULT: unknown fault \"" + std::string(name) +
                                "\" (known: no-compute-queue, no-float64, device-lost, device-hang, "
                                "out-of-device-memory, pipeline-fails-once)");
}

}  // namespace

InjectedFault injectedVulkanFault() {
    static const InjectedFault fault = parse(std::getenv("HEXRAY_INJECT_VULKAN_FAULT"));
    return fault;
}

bool injectedOnce(InjectedFault fault) {
    static std::atomic<bool> happened = false;
    return injected(fault) && !happened.exchange(true);
}

}  // namespace hexray::vulkan
