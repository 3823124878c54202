#include <cstdio>

#include "cli/command_support.h"

namespace hexray::cli {

int runDevices(const VulkanOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const VulkanContext context({options.validate ? &log : nullptr, options.device});
        for (const DeviceInfo& device : context.devices()) {
            const bool chosen = device.index == context.selected().index;
            const std::string driver = device.driver.empty() ? "" : device.driver + ", ";
            std::printf("%s%u: %s — %s, Vulkan %s, %s%s%s\n", chosen ? "* " : "  ", device.index, device.name.c_str(),
                        deviceTypeName(device.type).c_str(), device.apiVersion.c_str(), driver.c_str(),
                        device.hasComputeQueue ? "compute" : "no compute queue", device.hasFloat64 ? ", float64" : "");
        }
        std::printf("(* = the device hexray uses%s)\n", options.device.empty() ? " by default" : " with --device");
        return int(kSuccess);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
