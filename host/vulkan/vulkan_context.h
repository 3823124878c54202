#pragma once
// The one place that creates and destroys hexray's Vulkan instance, device and queue.
// Headless and compute-only: no surface, no window-system extension.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

namespace hexray::inline vulkan {

// Why the GPU path cannot render. Decides the exit code and whether `render --backend auto`
// may fall back to the CPU reference (every kind but Request).
enum class VulkanFailure {
    Unavailable,     // no driver or no device, or the instance or device could not be created
    NoComputeQueue,  // no device (or not the one named) has a compute queue
    NoFloat64,       // float64 was asked for and the device lacks shaderFloat64
    DeviceLost,      // lost during the render, or did not finish in time (hung)
    OutOfMemory,     // the driver reported out of device or host memory
    Request,         // what was asked is wrong: an unknown --device, a missing validation layer
};

// Vulkan cannot be used: no driver, no suitable device, or a call failed.
class VulkanError : public std::runtime_error {
public:
    // `advice` (what the user can do) is appended to what(), but not to reason().
    VulkanError(VulkanFailure failure, const std::string& reason, const std::string& advice = "")
        : std::runtime_error(advice.empty() ? reason : reason + ": " + advice), failure_(failure), reason_(reason) {}

    VulkanFailure failure() const { return failure_; }
    const std::string& reason() const { return reason_; }

private:
    VulkanFailure failure_;
    std::string reason_;
};

// A raw vulkan.hpp exception as a VulkanError of the right kind; `during` names the operation.
VulkanError classify(const vk::SystemError& error, const std::string& during);

struct DeviceInfo {
    std::uint32_t index = 0;  // as enumerated by the loader
    std::string name;
    vk::PhysicalDeviceType type = vk::PhysicalDeviceType::eOther;
    std::string driver;
    std::string apiVersion;
    bool hasComputeQueue = false;
    bool hasFloat64 = false;
    std::uint32_t maxTexelBufferElements = 0;
    // Where a buffer may take the host's own memory (VK_EXT_external_memory_host), how its start
    // and size must be aligned; 0 where it may not: only a CPU device, whose memory is the host's,
    // reads imported memory as fast as its own (a GPU would read it across the bus).
    std::uint64_t hostImportAlignment = 0;
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
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    // Submits `commands` and waits for `fence` at most `timeout`; safe to call from several threads
    // (each with its own command buffer and fence: `hexray watch` renders on two). Throws VulkanError:
    // DeviceLost when the device is lost, or when it does not finish in time, in which case
    // the device is abandoned (never destroyed: vkDestroyDevice would wait for the hung work).
    void submitAndWait(const vk::raii::CommandBuffer& commands, const vk::raii::Fence& fence,
                       std::chrono::nanoseconds timeout) const;

    // Whether a submission timed out. The hung work may still read and write whatever it
    // uses, so the owners of those objects (GpuRenderer) leak them instead of destroying them.
    bool abandoned() const { return abandoned_; }

    // All devices the loader reports, in its order.
    std::vector<DeviceInfo> devices() const;

    const DeviceInfo& selected() const { return selected_; }
    const vk::raii::PhysicalDevice& physicalDevice() const { return physicalDevice_; }
    const vk::raii::Device& device() const { return device_; }
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
    mutable std::mutex queueMutex_;                // vkQueueSubmit needs the queue externally synchronized
    mutable std::atomic<bool> abandoned_ = false;  // the device hung: leak it and the instance at teardown
};

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU" or "other".
std::string deviceTypeName(vk::PhysicalDeviceType type);

}  // namespace hexray::vulkan
