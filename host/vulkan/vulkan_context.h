#pragma once
// The one place that creates and destroys hexray's Vulkan instance, device and queue.
// Headless and compute-only: no surface, no window-system extension.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

namespace hexray {

// Vulkan cannot be used: no driver, no suitable device, or a call failed.
class VulkanError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct DeviceInfo {
    std::uint32_t index = 0;  // as enumerated by the loader
    std::string name;
    vk::PhysicalDeviceType type = vk::PhysicalDeviceType::eOther;
    std::string driver;
    std::string apiVersion;
    bool hasComputeQueue = false;
    bool hasFloat64 = false;
};

// Counts the validation layer's warnings and errors (each is also printed to stderr). Owned by
// the caller and outliving the context, so messages from the context's own teardown count too.
struct ValidationLog {
    std::atomic<std::uint32_t> messageCount{0};

    // The message ids seen ("SYNC-HAZARD-WRITE-AFTER-WRITE", "VUID-..."), so a test can tell
    // which check spoke.
    std::vector<std::string> messageIds() const {
        const std::lock_guard lock(mutex);
        return ids;
    }
    void record(const char* id) {
        const std::lock_guard lock(mutex);
        ids.emplace_back(id ? id : "");
        ++messageCount;
    }

private:
    mutable std::mutex mutex;
    std::vector<std::string> ids;
};

class VulkanContext {
public:
    struct Options {
        // Non-null: enable VK_LAYER_KHRONOS_validation, with synchronization validation, and
        // count its messages into this log.
        ValidationLog* validation = nullptr;
        std::string deviceSelector;  // index or part of a name; empty = best available
    };

    explicit VulkanContext(const Options& options);

    // All devices the loader reports, in its order.
    std::vector<DeviceInfo> devices() const;

    const DeviceInfo& selected() const { return selected_; }
    const vk::raii::PhysicalDevice& physicalDevice() const { return physicalDevice_; }
    const vk::raii::Device& device() const { return device_; }
    const vk::raii::Queue& queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }

private:
    // Declaration order is construction order; destruction runs in reverse.
    ValidationLog* validation_;
    vk::raii::Context context_;
    vk::raii::Instance instance_;
    vk::raii::DebugUtilsMessengerEXT messenger_;
    DeviceInfo selected_;
    vk::raii::PhysicalDevice physicalDevice_;
    std::uint32_t queueFamily_ = 0;
    vk::raii::Device device_;
    vk::raii::Queue queue_;
};

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU" or "other".
std::string deviceTypeName(vk::PhysicalDeviceType type);

}  // namespace hexray
