// UninitializedVector's storage starts on a page and spans whole pages: what a Vulkan device
// needs to import it (gpu/candidate_buffers.h).

#include <cstdint>

#include <gtest/gtest.h>

#include "util/uninitialized_vector.h"

namespace hexray {
namespace {

TEST(UninitializedVector, StartsOnAPageAtAnySize) {
    constexpr std::size_t kPage = DefaultInitAllocator<std::uint32_t>::kPageBytes;
    for (const std::size_t count : {std::size_t{1}, std::size_t{1000}, std::size_t{1025}, std::size_t{1} << 20}) {
        UninitializedVector<std::uint32_t> words(count);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(words.data()) % kPage, 0u) << count << " words";
        words.back() = 7;  // the last word is there to write
        EXPECT_EQ(words.back(), 7u);
    }
}

}  // namespace
}  // namespace hexray
