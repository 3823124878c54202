// "Did you mean …": edit distances and which name is suggested, or none.

#include "util/closest_name.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

using namespace hexray;

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("color", "colr"), 1u);
    EXPECT_EQ(editDistance("colour", "color"), 1u);
    EXPECT_EQ(editDistance("raduis", "radius"), 1u);  // one swap, not two substitutions
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("fvo", "fov"), 1u);
}

TEST(ClosestName, SuggestsTheNearestWithinTwoEdits) {
    const std::vector<std::string> keys = {"aspect", "fov", "lookAt", "pitch", "position", "roll", "up", "yaw"};
    EXPECT_EQ(closestName("fvo", keys), "fov");
    EXPECT_EQ(closestName("lookat", keys), "lookAt");
    EXPECT_EQ(closestName("postion", keys), "position");
    EXPECT_EQ(closestName("pitchh", keys), "pitch");
}

TEST(ClosestName, SuggestsNothingFarShortOrExact) {
    const std::vector<std::string> keys = {"width", "height", "spp"};
    EXPECT_EQ(closestName("depth", keys), std::nullopt);  // 3 edits from "width"
    EXPECT_EQ(closestName("x", {"y"}), std::nullopt);     // any one-letter key is one edit away
    EXPECT_EQ(closestName("sp", keys), std::nullopt);     // too short to guess from
    EXPECT_EQ(closestName("width", keys), std::nullopt);  // no typo
    EXPECT_EQ(closestName("", keys), std::nullopt);
    EXPECT_EQ(closestName(std::string(1000, 'w'), keys), std::nullopt);
}

TEST(ClosestName, TiesGoToTheFirstCandidate) {
    EXPECT_EQ(closestName("bal", {"ball", "bale"}), "ball");
    EXPECT_EQ(closestName("bal", {"bale", "ball"}), "bale");
}
