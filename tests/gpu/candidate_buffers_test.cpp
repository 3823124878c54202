// The candidate lists on the device: a CPU device that imports host memory takes the lists' cell
// starts and entries as they are (the host holds them once); any other gets copies. Either way the
// buffers hold the lists' words.

#include <cstring>
#include <memory>

#include <gtest/gtest.h>

#include "accel/candidate_lists.h"
#include "gpu/candidate_buffers.h"
#include "gpu/render_plan.h"
#include "gpu/validated_vulkan.h"
#include "scene/random_spheres.h"

namespace hexray {
namespace {

class CandidateBuffersTest : public test::ValidatedVulkanTest {
protected:
    static std::shared_ptr<const CandidateLists> listsOf(const Scene& scene) {
        auto lists =
            buildCandidateLists(scene, placementFor(scene, Formulation::Robust), FloatWidth::F32, Formulation::Robust);
        return lists ? std::make_shared<const CandidateLists>(std::move(*lists)) : nullptr;
    }

    CandidateBuffers buffersOf(std::shared_ptr<const CandidateLists> lists, vk::DeviceSize importAlignment) const {
        return CandidateBuffers(context().device(), context().physicalDevice(), std::move(lists), {}, importAlignment);
    }
};

template <typename Words>
bool holds(std::span<const std::byte> buffer, const Words& words) {
    const std::size_t bytes = words.size() * sizeof(words[0]);
    return buffer.size() >= bytes && std::memcmp(buffer.data(), words.data(), bytes) == 0;
}

TEST_F(CandidateBuffersTest, ACpuDeviceImportsTheListsWordsAndOthersGetCopies) {
    Scene scene = makeRandomSpheresScene(3000, 7);
    const auto lists = listsOf(scene);
    ASSERT_TRUE(lists);
    ASSERT_GT(lists->entries.size() * sizeof(std::uint32_t), 4096u);  // past a page: worth importing
    const vk::DeviceSize alignment = context().selected().hostImportAlignment;
    if (onLavapipe()) {
        ASSERT_NE(alignment, 0u) << "lavapipe imports host memory (VK_EXT_external_memory_host)";
    }
    if (alignment == 0) {
        GTEST_SKIP() << context().selected().name << " imports no host memory";
    }
    const CandidateBuffers imported = buffersOf(lists, alignment);
    EXPECT_EQ(imported.contents(gpu::CANDIDATE_ENTRY_BINDING).data(),
              reinterpret_cast<const std::byte*>(lists->entries.data()));
    EXPECT_EQ(imported.contents(gpu::CANDIDATE_CELL_BINDING).data(),
              reinterpret_cast<const std::byte*>(lists->cellStarts.data()));
    const CandidateBuffers copied = buffersOf(lists, 0);
    EXPECT_NE(copied.contents(gpu::CANDIDATE_ENTRY_BINDING).data(),
              reinterpret_cast<const std::byte*>(lists->entries.data()));
    for (const CandidateBuffers* buffers : {&imported, &copied}) {
        EXPECT_TRUE(holds(buffers->contents(gpu::CANDIDATE_ENTRY_BINDING), lists->entries));
        EXPECT_TRUE(holds(buffers->contents(gpu::CANDIDATE_CELL_BINDING), lists->cellStarts));
        EXPECT_TRUE(holds(buffers->contents(gpu::CANDIDATE_GRID_BINDING), lists->gridBytes()));
    }
}

TEST_F(CandidateBuffersTest, TheImportedListsOutliveEveryOtherHolder) {
    Scene scene = makeRandomSpheresScene(3000, 7);
    auto lists = listsOf(scene);
    ASSERT_TRUE(lists);
    const std::vector<std::uint32_t> entries(lists->entries.begin(), lists->entries.end());
    const CandidateBuffers buffers = buffersOf(std::move(lists), context().selected().hostImportAlignment);
    EXPECT_TRUE(holds(buffers.contents(gpu::CANDIDATE_ENTRY_BINDING), entries));
}

}  // namespace
}  // namespace hexray
