// Strips' rows and the stamp a piece records: every row in exactly one strip, and a stamp read
// back exactly as written, anything else refused.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "strip/strip_stamp.h"

namespace hexray {
namespace {

TEST(Strip, StripsCoverEveryRowOnceAndDifferInHeightByAtMostOne) {
    for (const std::uint32_t height : {1u, 7u, 53u, 480u, 16384u}) {
        for (const std::uint32_t count : {1u, 2u, 3u, 7u, 8u}) {
            if (count > height)
                continue;
            std::uint32_t next = 0;
            for (std::uint32_t index = 0; index < count; ++index) {
                const RowRange rows = stripRows({index, count}, height);
                EXPECT_EQ(rows.first, next);
                EXPECT_GE(rows.count, height / count);
                EXPECT_LE(rows.count, height / count + 1);
                next = rows.end();
            }
            EXPECT_EQ(next, height);
        }
    }
    EXPECT_THROW(stripRows({0, 5}, 4), StripError);
}

TEST(StripStamp, ReadsBackExactlyWhatItWrote) {
    const StripStamp stamp{{3, 8},
                           640,
                           480,
                           4,
                           "gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); odd; hexray x",
                           "0123456789abcdef/99",
                           "0.1.0 (git 0123456789ab)"};
    const std::string text = formatStripStamp(stamp);
    EXPECT_EQ(text,
              "3/8 rows 180-239 of 640x480; spp 4; gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); odd; hexray x; "
              "scene 0123456789abcdef/99; hexray 0.1.0 (git 0123456789ab)");
    const std::optional<StripStamp> read = parseStripStamp(text);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->strip, stamp.strip);
    EXPECT_EQ(read->renderer, stamp.renderer);
    EXPECT_EQ(read->version, stamp.version);
    EXPECT_TRUE(read->sameImage(stamp));
    StripStamp otherBuild = stamp;
    otherBuild.version = "0.1.0 (git 0123456789ac)";
    EXPECT_FALSE(otherBuild.sameImage(stamp));
}

TEST(StripStamp, AnythingElseIsNoStamp) {
    const std::string version = "; hexray 0.1.0 (git 0123456789ab)";
    for (const std::string& text : std::vector<std::string>{
             "", "3/8", "3/8 rows 181-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1" + version,
             "8/8 rows 480-479 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1" + version,
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1 extra" + version,
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdeg/1" + version,
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference" + version,
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1",
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1; hexray ",
             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1; hexray a\tb",
             "3/9 rows 0-0 of 640x1; spp 4; cpu reference; scene 0123456789abcdef/1" + version}) {
        EXPECT_FALSE(parseStripStamp(text)) << text;
    }
    EXPECT_TRUE(
        parseStripStamp("3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1" + version));
}

TEST(StripStamp, AnImageTheRendererCannotMakeIsNamed) {
    StripStamp stamp{{0, 1}, 16384, 16384, 16, "cpu reference", "0123456789abcdef/1", "0.1.0"};
    EXPECT_EQ(beyondRendererLimits(stamp), std::nullopt);
    stamp.width = 16385;
    EXPECT_EQ(beyondRendererLimits(stamp),
              "its stamp declares a 16385x16384 image, larger than hexray renders (at most 16384x16384)");
    stamp.width = 16384;
    stamp.samplesPerPixel = 17;  // 16384^2 * 17 > 2^32 samples
    EXPECT_EQ(beyondRendererLimits(stamp),
              "its stamp declares 16384x16384 pixels at spp 17, more samples than hexray "
              "renders (spp at most 1024, 4294967296 samples an image)");
    stamp = {{0, 1}, 4, 4, 1025, "cpu reference", "0123456789abcdef/1", "0.1.0"};
    EXPECT_TRUE(beyondRendererLimits(stamp));
}

TEST(StripStamp, SceneIdentityIsTheTextsHashAndSize) {
    EXPECT_EQ(sceneTextIdentity("{}"), sceneTextIdentity(std::string("{}")));
    EXPECT_NE(sceneTextIdentity("{} "), sceneTextIdentity("{}"));
    EXPECT_EQ(sceneTextIdentity("abc").substr(16), "/3");
}

}  // namespace
}  // namespace hexray
