// `hexray --version`: what a bug report needs to say about this hexray and the Vulkan under it.

#include <cstdio>
#include <string>

#include "cli/command_support.h"
#include "util/build_version.h"

namespace hexray::cli {
namespace {

std::string versionText(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

// The device hexray would use and its driver, or why there is none.
std::string deviceLine() {
    try {
        const VulkanContext context({nullptr, ""});
        const DeviceInfo& device = context.selected();
        return device.name + " — " + deviceTypeName(device.type) + ", Vulkan " + device.apiVersion + ", driver " +
               (device.driver.empty() ? "unnamed (Vulkan 1.1 device)" : device.driver);
    } catch (const VulkanError& error) {
        return "none: Vulkan is unavailable (" + error.reason() + ")";
    } catch (const vk::SystemError& error) {
        return "none: Vulkan is unavailable (" + classify(error, "starting Vulkan").reason() + ")";
    }
}

}  // namespace

int runVersion() {
    std::printf("hexray %s\n", buildVersion().c_str());
    std::string loader;
    try {
        loader = versionText(vk::raii::Context().enumerateInstanceVersion());
    } catch (const std::exception& error) {
        loader = std::string("unknown (") + error.what() + ")";
    }
    std::printf("Vulkan loader %s\n", loader.c_str());
    std::printf("device: %s\n", deviceLine().c_str());
    return kSuccess;
}

}  // namespace hexray::cli
