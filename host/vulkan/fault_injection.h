#pragma once
// Test hook: HEXRAY_INJECT_VULKAN_FAULT makes one Vulkan fault happen that lavapipe cannot
// produce on demand, at the place where the real one would arise, so the real handling runs:
//   no-compute-queue      the devices' queue families report no compute bit
//   no-float64            the devices' features report no shaderFloat64
//   device-lost           the fence wait of a render ends in VK_ERROR_DEVICE_LOST
//   device-hang           the fence wait of a render times out at once (the work still running)
//   out-of-device-memory  the render's buffer allocation fails with VK_ERROR_OUT_OF_DEVICE_MEMORY
//   pipeline-fails-once   the process's first compute pipeline creation fails with VK_ERROR_UNKNOWN,
//                         as lavapipe's does for SPIR-V it cannot compile
// Unset or empty: no fault. Any other value is an error, so a mistyped test cannot pass quietly.

#include <string_view>

namespace hexray::inline vulkan {

enum class InjectedFault {
    None,
    NoComputeQueue,
    NoFloat64,
    DeviceLost,
    DeviceHang,
    OutOfDeviceMemory,
    PipelineFailsOnce
};

// Read once per process; throws std::invalid_argument for an unknown value.
InjectedFault injectedVulkanFault();

inline bool injected(InjectedFault fault) {
    return injectedVulkanFault() == fault;
}

// True the first time it is asked in this process when `fault` is the one injected. Thread-safe.
bool injectedOnce(InjectedFault fault);

}  // namespace hexray::vulkan
