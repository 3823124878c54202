// Device selection and the validation hook the GPU tests rely on.

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "vulkan/host_visible_buffer.h"
#include "vulkan/vulkan_context.h"

namespace hexray {
namespace {

TEST(VulkanContext, ValidationLayerReportsMisuse) {
    // The GPU tests pass only if this hook would have caught something: prove it does by
    // breaking a rule on purpose (a buffer must have at least one usage flag).
    ValidationLog log;
    {
        const VulkanContext context({&log, ""});
        const vk::BufferCreateInfo invalid({}, 64, vk::BufferUsageFlags(), vk::SharingMode::eExclusive);
        const vk::raii::Buffer buffer(context.device(), invalid);
    }
    EXPECT_GT(log.messageCount.load(), 0u);
}

TEST(VulkanContext, SynchronizationValidationReportsAHazard) {
    // The GPU tests' silence proves the renderer's barriers only if synchronization validation
    // is on: two transfer writes to one buffer with no barrier between them must be reported.
    ValidationLog log;
    {
        const VulkanContext context({&log, ""});
        const HostVisibleBuffer buffer(context.device(), context.physicalDevice(), 256,
                                       vk::BufferUsageFlagBits::eTransferDst);
        const vk::raii::CommandPool pool(context.device(), vk::CommandPoolCreateInfo({}, context.queueFamily()));
        vk::raii::CommandBuffers commands(context.device(),
                                          vk::CommandBufferAllocateInfo(*pool, vk::CommandBufferLevel::ePrimary, 1));
        commands[0].begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
        commands[0].fillBuffer(*buffer.buffer(), 0, VK_WHOLE_SIZE, 1);
        commands[0].fillBuffer(*buffer.buffer(), 0, VK_WHOLE_SIZE, 2);  // write after write, unsynchronized
        commands[0].end();
    }
    const std::vector<std::string> ids = log.messageIds();
    EXPECT_TRUE(std::any_of(ids.begin(), ids.end(),
                            [](const std::string& id) { return id.starts_with("SYNC-HAZARD-WRITE-AFTER-WRITE"); }))
        << ids.size() << " message(s), none a SYNC-HAZARD-WRITE-AFTER-WRITE";
}

TEST(VulkanContext, CleanUseIsSilent) {
    ValidationLog log;
    { const VulkanContext context({&log, ""}); }
    EXPECT_EQ(log.messageCount.load(), 0u);
}

TEST(VulkanContext, SelectsByIndexAndByPartOfTheName) {
    const VulkanContext byDefault({nullptr, ""});
    const DeviceInfo chosen = byDefault.selected();
    EXPECT_TRUE(chosen.hasComputeQueue);

    const VulkanContext byIndex({nullptr, std::to_string(chosen.index)});
    EXPECT_EQ(byIndex.selected().name, chosen.name);

    std::string lowercasePart = chosen.name.substr(0, 4);
    for (char& c : lowercasePart) {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    const VulkanContext byName({nullptr, lowercasePart});
    EXPECT_EQ(byName.selected().name.substr(0, 4), chosen.name.substr(0, 4));
}

TEST(VulkanContext, UnknownSelectorListsTheDevices) {
    try {
        const VulkanContext context({nullptr, "no-such-device"});
        FAIL() << "expected VulkanError";
    } catch (const VulkanError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("no Vulkan device matches --device no-such-device"), std::string::npos) << message;
        EXPECT_NE(message.find("0: "), std::string::npos) << message;
    }
    EXPECT_THROW(VulkanContext({nullptr, "999"}), VulkanError);
}

TEST(VulkanContext, PrefersARealGpuOverTheCpuImplementation) {
    const VulkanContext context({nullptr, ""});
    const auto devices = context.devices();
    const bool anyGpu = std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& d) {
        return d.hasComputeQueue &&
               (d.type == vk::PhysicalDeviceType::eDiscreteGpu || d.type == vk::PhysicalDeviceType::eIntegratedGpu);
    });
    if (anyGpu) {
        EXPECT_NE(context.selected().type, vk::PhysicalDeviceType::eCpu);
    } else {
        EXPECT_EQ(context.selected().type, vk::PhysicalDeviceType::eCpu) << "lavapipe is the fallback";
    }
}

}  // namespace
}  // namespace hexray
