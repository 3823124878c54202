// reduceAcrossCores folds every item exactly once, on as many parts as cores allow, and merges
// the parts' results in order.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "util/parallel_parts.h"

namespace hexray {
namespace {

struct Tally {
    std::uint64_t sum = 0;
    std::size_t count = 0;
    std::vector<std::size_t> firstOfEachPart;
};

Tally tallyAcrossCores(std::size_t count, std::size_t leastPerPart) {
    return reduceAcrossCores(
        count, leastPerPart, Tally{},
        [](Tally& part, std::size_t i) {
            if (part.count++ == 0) {
                part.firstOfEachPart.push_back(i);
            }
            part.sum += i;
        },
        [](Tally& total, const Tally& part) {
            total.sum += part.sum;
            total.count += part.count;
            total.firstOfEachPart.insert(total.firstOfEachPart.end(), part.firstOfEachPart.begin(),
                                         part.firstOfEachPart.end());
        });
}

TEST(ReduceAcrossCores, FoldsEveryItemOnceAndMergesThePartsInOrder) {
    const std::size_t count = 100000;
    const Tally tally = tallyAcrossCores(count, 1000);
    EXPECT_EQ(tally.count, count);
    EXPECT_EQ(tally.sum, std::uint64_t(count) * (count - 1) / 2);
    const unsigned parts = partsAcrossCores(count, 1000);
    ASSERT_EQ(tally.firstOfEachPart.size(), parts);
    for (unsigned part = 0; part < parts; ++part) {
        EXPECT_EQ(tally.firstOfEachPart[part], partBegin(count, parts, part));
    }
}

TEST(ReduceAcrossCores, GivesItsStartingValueForNoItems) {
    const Tally tally = tallyAcrossCores(0, 1000);
    EXPECT_EQ(tally.count, 0u);
    EXPECT_TRUE(tally.firstOfEachPart.empty());
}

}  // namespace
}  // namespace hexray
