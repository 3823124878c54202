#include "vulkan/vulkan_context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <string_view>

#include "vulkan/fault_injection.h"

namespace hexray::inline vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::uint32_t kApiVersion = VK_API_VERSION_1_2;

constexpr const char* kNoDeviceAdvice =
    "install a Vulkan driver (on Debian: apt-get install mesa-vulkan-drivers, which provides "
    "lavapipe, a CPU implementation) or render with --backend cpu";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
    const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    // General messages come from the loader ("Found no drivers!" when there is none): that
    // fault has its own message and exit code, so they are shown but do not fail validation.
    if (types == VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT) {
        std::fprintf(stderr, "hexray: Vulkan loader %s: %s\n", level, data->pMessage);
        return VK_FALSE;
    }
    static_cast<ValidationLog*>(userData)->record(data->pMessageIdName);
    std::fprintf(stderr, "hexray: Vulkan validation %s: %s\n", level, data->pMessage);
    return VK_FALSE;
}

vk::DebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
    using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
    using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
    return vk::DebugUtilsMessengerCreateInfoEXT({}, Severity::eWarning | Severity::eError,
                                                Type::eGeneral | Type::eValidation | Type::ePerformance,
                                                &onValidationMessage, log);
}

bool hasLayer(const vk::raii::Context& context, std::string_view name) {
    const auto layers = context.enumerateInstanceLayerProperties();
    return std::any_of(layers.begin(), layers.end(),
                       [&](const vk::LayerProperties& layer) { return name == layer.layerName.data(); });
}

vk::raii::Instance createInstance(const vk::raii::Context& context, ValidationLog* validation) {
    const vk::ApplicationInfo application("hexray", 1, "hexray", 1, kApiVersion);
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    vk::InstanceCreateInfo info({}, &application);
    // Also report problems during instance creation.
    vk::DebugUtilsMessengerCreateInfoEXT creationMessenger =
        validation ? messengerInfo(validation) : vk::DebugUtilsMessengerCreateInfoEXT();
    // Synchronization validation is off by default in the layer: missing barriers between the
    // dispatch and the host's reads would otherwise pass unnoticed.
    const vk::ValidationFeatureEnableEXT enables[] = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
    const vk::ValidationFeaturesEXT synchronization(enables, {}, &creationMessenger);
    if (validation) {
        if (!hasLayer(context, kValidationLayer)) {
            throw VulkanError(VulkanFailure::Request,
                              std::string("validation was requested but ") + kValidationLayer + " is not installed",
                              "on Debian: apt-get install vulkan-validationlayers");
        }
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);  // provided by the layer
        info.pNext = &synchronization;
    }
    info.setPEnabledLayerNames(layers);
    info.setPEnabledExtensionNames(extensions);
    try {
        return vk::raii::Instance(context, info);
    } catch (const vk::IncompatibleDriverError&) {
        throw VulkanError(VulkanFailure::Unavailable, "no Vulkan driver found", kNoDeviceAdvice);
    } catch (const vk::SystemError& error) {
        throw classify(error, "creating a Vulkan instance");
    }
}

// Real GPUs first; lavapipe (a CPU device) is the fallback that always works.
int preference(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu:
            return 4;
        case vk::PhysicalDeviceType::eIntegratedGpu:
            return 3;
        case vk::PhysicalDeviceType::eVirtualGpu:
            return 2;
        case vk::PhysicalDeviceType::eCpu:
            return 1;
        default:
            return 0;
    }
}

std::optional<std::uint32_t> computeQueueFamily(const vk::raii::PhysicalDevice& device) {
    const auto families = device.getQueueFamilyProperties();
    for (std::uint32_t i = 0; i < families.size(); ++i) {
        if (families[i].queueFlags & vk::QueueFlagBits::eCompute && !injected(InjectedFault::NoComputeQueue)) {
            return i;
        }
    }
    return std::nullopt;
}

DeviceInfo describe(const vk::raii::PhysicalDevice& device, std::uint32_t index) {
    const vk::PhysicalDeviceProperties properties = device.getProperties();
    DeviceInfo info;
    info.index = index;
    info.name = properties.deviceName.data();
    info.type = properties.deviceType;
    info.apiVersion = std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                      std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + "." +
                      std::to_string(VK_API_VERSION_PATCH(properties.apiVersion));
    if (properties.apiVersion >= VK_API_VERSION_1_2) {
        const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
        const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
        info.driver = std::string(driver.driverName.data()) + " " + driver.driverInfo.data();
    }
    info.hasComputeQueue = computeQueueFamily(device).has_value();
    info.hasFloat64 = device.getFeatures().shaderFloat64 == VK_TRUE && !injected(InjectedFault::NoFloat64);
    info.maxTexelBufferElements = device.getProperties().limits.maxTexelBufferElements;
    const auto extensions = device.enumerateDeviceExtensionProperties();
    const bool importsHostMemory = std::ranges::any_of(extensions, [](const vk::ExtensionProperties& extension) {
        return std::string_view(extension.extensionName.data()) == VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME;
    });
    if (importsHostMemory && info.type == vk::PhysicalDeviceType::eCpu) {
        const auto chain =
            device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceExternalMemoryHostPropertiesEXT>();
        info.hostImportAlignment =
            chain.get<vk::PhysicalDeviceExternalMemoryHostPropertiesEXT>().minImportedHostPointerAlignment;
    }
    return info;
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::string listForMessage(const std::vector<DeviceInfo>& devices) {
    std::string list;
    for (const DeviceInfo& device : devices) {
        list += (list.empty() ? "" : ", ") + std::to_string(device.index) + ": " + device.name;
    }
    return list;
}

std::vector<DeviceInfo> describeAll(const vk::raii::PhysicalDevices& physicalDevices) {
    std::vector<DeviceInfo> devices;
    for (std::uint32_t i = 0; i < physicalDevices.size(); ++i) {
        devices.push_back(describe(physicalDevices[i], i));
    }
    return devices;
}

// Picks by index or by case-insensitive part of the name; with no selector, the most capable.
std::uint32_t selectDevice(const std::vector<DeviceInfo>& devices, const std::string& selector) {
    if (devices.empty()) {
        throw VulkanError(VulkanFailure::Unavailable, "no Vulkan device found", kNoDeviceAdvice);
    }
    if (selector.empty()) {
        std::optional<std::uint32_t> best;
        for (const DeviceInfo& device : devices) {
            if (device.hasComputeQueue && (!best || preference(device.type) > preference(devices[*best].type))) {
                best = device.index;
            }
        }
        if (!best) {
            throw VulkanError(VulkanFailure::NoComputeQueue,
                              "no Vulkan device has a compute queue (devices: " + listForMessage(devices) + ")",
                              "render with --backend cpu");
        }
        return *best;
    }
    const bool isIndex = std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
    for (const DeviceInfo& device : devices) {
        const bool matches = isIndex ? std::to_string(device.index) == selector
                                     : lowercase(device.name).find(lowercase(selector)) != std::string::npos;
        if (matches) {
            if (!device.hasComputeQueue) {
                throw VulkanError(VulkanFailure::NoComputeQueue, "device " + std::to_string(device.index) + " (" +
                                                                     device.name + ") has no compute queue");
            }
            return device.index;
        }
    }
    throw VulkanError(VulkanFailure::Request,
                      "no Vulkan device matches --device " + selector + " (devices: " + listForMessage(devices) + ")");
}

}  // namespace

VulkanError classify(const vk::SystemError& error, const std::string& during) {
    const std::string what = error.code().message();  // e.g. "ErrorDeviceLost"
    switch (vk::Result(error.code().value())) {
        case vk::Result::eErrorDeviceLost:
            return VulkanError(VulkanFailure::DeviceLost, "the Vulkan device was lost while " + during + " (" + what +
                                                              ": a driver crash or a GPU reset)");
        case vk::Result::eErrorOutOfDeviceMemory:
        case vk::Result::eErrorOutOfHostMemory:
            return VulkanError(VulkanFailure::OutOfMemory, "out of memory while " + during + " (" + what + ")",
                               "try a smaller image (--width/--height) or --backend cpu");
        case vk::Result::eErrorIncompatibleDriver:
            return VulkanError(VulkanFailure::Unavailable, "no Vulkan driver found", kNoDeviceAdvice);
        default:
            return VulkanError(VulkanFailure::Unavailable, "Vulkan failed while " + during + ": " + error.what());
    }
}

std::string deviceTypeName(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu:
            return "discrete GPU";
        case vk::PhysicalDeviceType::eIntegratedGpu:
            return "integrated GPU";
        case vk::PhysicalDeviceType::eVirtualGpu:
            return "virtual GPU";
        case vk::PhysicalDeviceType::eCpu:
            return "CPU";
        default:
            return "other";
    }
}

VulkanContext::VulkanContext(const Options& options)
    : validation_(options.validation),
      instance_(createInstance(context_, validation_)),
      messenger_(validation_ ? vk::raii::DebugUtilsMessengerEXT(instance_, messengerInfo(validation_))
                             : vk::raii::DebugUtilsMessengerEXT(nullptr)),
      physicalDevice_(nullptr),
      device_(nullptr),
      queue_(nullptr) {
    const vk::raii::PhysicalDevices physicalDevices(instance_);
    const std::vector<DeviceInfo> all = describeAll(physicalDevices);
    const std::uint32_t index = selectDevice(all, options.deviceSelector);
    selected_ = all[index];
    physicalDevice_ = physicalDevices[index];
    queueFamily_ = *computeQueueFamily(physicalDevice_);

    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queueInfo({}, queueFamily_, 1, &priority);
    // float64 only if the device has it; the f64 shader variant checks before it is used.
    vk::PhysicalDeviceFeatures features;
    features.shaderFloat64 = selected_.hasFloat64 ? VK_TRUE : VK_FALSE;
    std::vector<const char*> extensions;
    if (selected_.hostImportAlignment != 0) {
        extensions.push_back(VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME);
    }
    try {
        device_ = vk::raii::Device(physicalDevice_, vk::DeviceCreateInfo({}, queueInfo, {}, extensions, &features));
    } catch (const vk::SystemError& error) {
        throw classify(error, "creating a Vulkan device on " + selected_.name);
    }
    queue_ = vk::raii::Queue(device_, queueFamily_, 0);
}

VulkanContext::~VulkanContext() {
    if (abandoned_) {
        // Destroying a device with work still pending would block on it, or worse.
        queue_.release();
        device_.release();
        messenger_.release();
        instance_.release();
    }
}

void VulkanContext::submitAndWait(const vk::raii::CommandBuffer& commands, const vk::raii::Fence& fence,
                                  std::chrono::nanoseconds timeout) const {
    vk::Result result;
    try {
        {
            const std::lock_guard lock(queueMutex_);
            queue_.submit(vk::SubmitInfo({}, {}, *commands), *fence);
        }
        // An injected hang does not wait, so the abandoned work is still running, as a real
        // hang's would be.
        const bool hang = injected(InjectedFault::DeviceHang);
        result = device_.waitForFences(*fence, VK_TRUE, hang ? 0 : std::uint64_t(timeout.count()));
        if (injected(InjectedFault::DeviceLost)) {
            throw vk::DeviceLostError("vkWaitForFences");
        }
        if (hang) {
            result = vk::Result::eTimeout;
        }
    } catch (const vk::SystemError& error) {
        throw classify(error, "rendering on " + selected_.name);
    }
    if (result == vk::Result::eTimeout) {
        abandoned_ = true;
        const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(timeout).count();
        throw VulkanError(VulkanFailure::DeviceLost, "the Vulkan device timed out: a render did not finish within " +
                                                         std::to_string(seconds) + " s on " + selected_.name +
                                                         ", which is treated as hung");
    }
}

std::vector<DeviceInfo> VulkanContext::devices() const {
    return describeAll(vk::raii::PhysicalDevices(instance_));
}

}  // namespace hexray::vulkan
