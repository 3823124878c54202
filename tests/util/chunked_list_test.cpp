// Values appended to a ChunkedList come back, in order, as one vector of just their number.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "util/chunked_list.h"

namespace hexray {
namespace {

TEST(ChunkedList, GivesBackEveryValueInOrderAcrossChunks) {
    ChunkedList<std::uint64_t> list;
    const std::uint64_t count = 3 * ChunkedList<std::uint64_t>::kMaxChunkBytes / sizeof(std::uint64_t) + 17;
    for (std::uint64_t i = 0; i < count; ++i) {
        list.push_back(i * 7);
    }
    EXPECT_EQ(list.size(), count);
    const std::vector<std::uint64_t> values = std::move(list).take();
    ASSERT_EQ(values.size(), count);
    EXPECT_EQ(values.capacity(), count);
    for (std::uint64_t i = 0; i < count; ++i) {
        ASSERT_EQ(values[i], i * 7) << i;
    }
    EXPECT_EQ(list.size(), 0u);
}

TEST(ChunkedList, EmptyGivesAnEmptyVector) {
    EXPECT_TRUE(ChunkedList<int>().take().empty());
}

}  // namespace
}  // namespace hexray
