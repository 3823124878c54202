// Edit distances and the nearest known word, as the "did you mean …" hints use them.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "util/edit_distance.h"

namespace hexray {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsReplacementsAndSwaps) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("render", "render"), 0u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("rendr", "render"), 1u);
    EXPECT_EQ(editDistance("renderr", "render"), 1u);
    EXPECT_EQ(editDistance("rander", "render"), 1u);
    EXPECT_EQ(editDistance("--widht", "--width"), 1u);  // a swap of neighbours is one edit
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("compare", "render"), editDistance("render", "compare"));
}

TEST(EditDistance, TheNearestWordWithinTheLimitOrNone) {
    const std::vector<std::string> commands = {"render", "merge", "compare", "diff", "bench", "pixel"};
    EXPECT_EQ(nearestWord("rendr", commands), "render");
    EXPECT_EQ(nearestWord("comprae", commands), "compare");
    EXPECT_EQ(nearestWord("dif", commands), "diff");
    EXPECT_EQ(nearestWord("frobnicate", commands), std::nullopt);
    EXPECT_EQ(nearestWord("rendxxx", commands), std::nullopt);  // three edits
    EXPECT_EQ(nearestWord("rendxxx", commands, 3), "render");
    EXPECT_EQ(nearestWord("merge", commands), "merge");
}

}  // namespace
}  // namespace hexray
