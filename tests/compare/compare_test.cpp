#include <cmath>

#include <gtest/gtest.h>

#include "compare/compare.h"

namespace hexray {
namespace {

Image filled(std::uint32_t width, std::uint32_t height, glm::vec3 color) {
    Image image(width, height);
    std::fill(image.pixels.begin(), image.pixels.end(), color);
    return image;
}

TEST(CompareLinear, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
    const Image a = filled(4, 3, {0.2f, 0.4f, 0.6f});
    const ErrorMetrics m = compareLinear(a, a);
    EXPECT_EQ(m.maxAbs, 0.0);
    EXPECT_EQ(m.rmse, 0.0);
    EXPECT_TRUE(std::isinf(m.psnr));
    EXPECT_EQ(m.pixelsOverOneLevel, 0u);
}

TEST(CompareLinear, OneChannelOfOnePixelOff) {
    const Image a = filled(10, 10, glm::vec3(0.5f));
    Image b = a;
    b.at(3, 7).g = 0.6f;  // 0.1 off, in one of 300 channels
    const ErrorMetrics m = compareLinear(a, b);
    EXPECT_NEAR(m.maxAbs, 0.1, 1e-6);
    EXPECT_NEAR(m.meanAbs, 0.1 / 300.0, 1e-8);
    EXPECT_NEAR(m.rmse, std::sqrt(0.01 / 300.0), 1e-7);
    EXPECT_NEAR(m.psnr, 20.0 * std::log10(1.0 / std::sqrt(0.01 / 300.0)), 1e-3);
    EXPECT_EQ(m.pixelsOverOneLevel, 1u);
    EXPECT_DOUBLE_EQ(m.shareOverOneLevel, 0.01);
}

TEST(CompareLinear, ComparesWhatTheOutputCanShow) {
    // Both over-exposed: the clamped output is identical.
    EXPECT_EQ(compareLinear(filled(2, 2, glm::vec3(1.5f)), filled(2, 2, glm::vec3(3.0f))).maxAbs, 0.0);
}

TEST(CompareEncoded, CountsOnlyPixelsMoreThanOneLevelApart) {
    Rgb8Image a{3, 1, {10, 10, 10, 10, 10, 10, 10, 10, 10}};
    Rgb8Image b{3, 1, {11, 10, 10, 10, 12, 10, 10, 10, 10}};
    const ErrorMetrics m = compareEncoded(a, b);
    EXPECT_EQ(m.maxAbs, 2.0);
    EXPECT_EQ(m.pixelsOverOneLevel, 1u);
    EXPECT_NEAR(m.meanAbs, 3.0 / 9.0, 1e-12);
}

TEST(Compare, SizeMismatchIsRejected) {
    EXPECT_THROW(compareLinear(filled(2, 2, {}), filled(2, 3, {})), std::invalid_argument);
}

TEST(DiffHeatMap, BlackWhereEqualBrighterWhereFurtherApart) {
    Rgb8Image a{3, 1, {0, 0, 0, 0, 0, 0, 0, 0, 0}};
    Rgb8Image b{3, 1, {0, 0, 0, 1, 0, 0, 255, 0, 0}};
    const Rgb8Image map = diffHeatMap(a, b);
    EXPECT_EQ(map.bytes[0] + map.bytes[1] + map.bytes[2], 0);
    const int oneLevel = map.bytes[3] + map.bytes[4] + map.bytes[5];
    const int full = map.bytes[6] + map.bytes[7] + map.bytes[8];
    EXPECT_GT(oneLevel, 0);
    EXPECT_EQ(full, 3 * 255);
}

}  // namespace
}  // namespace hexray
