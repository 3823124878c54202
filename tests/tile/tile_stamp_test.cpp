// Tiles' rows and the stamp a piece records: every row in exactly one tile, and a stamp read
// back exactly as written, anything else refused.

#include <string>

#include <gtest/gtest.h>

#include "tile/tile_stamp.h"

namespace hexray {
namespace {

TEST(Tile, TilesCoverEveryRowOnceAndDifferInHeightByAtMostOne) {
    for (const std::uint32_t height : {1u, 7u, 53u, 480u, 16384u}) {
        for (const std::uint32_t count : {1u, 2u, 3u, 7u, 8u}) {
            if (count > height) continue;
            std::uint32_t next = 0;
            for (std::uint32_t index = 0; index < count; ++index) {
                const RowRange rows = tileRows({index, count}, height);
                EXPECT_EQ(rows.first, next);
                EXPECT_GE(rows.count, height / count);
                EXPECT_LE(rows.count, height / count + 1);
                next = rows.end();
            }
            EXPECT_EQ(next, height);
        }
    }
    EXPECT_THROW(tileRows({0, 5}, 4), TileError);
}

TEST(TileStamp, ReadsBackExactlyWhatItWrote) {
    const TileStamp stamp{{3, 8}, 640, 480, 4, "gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); odd", "0123456789abcdef/99"};
    const std::string text = formatTileStamp(stamp);
    EXPECT_EQ(text, "3/8 rows 180-239 of 640x480; spp 4; gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); odd; "
                    "scene 0123456789abcdef/99");
    const std::optional<TileStamp> read = parseTileStamp(text);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->tile, stamp.tile);
    EXPECT_TRUE(read->sameImage(stamp));
}

TEST(TileStamp, AnythingElseIsNoStamp) {
    for (const char* text : {"", "3/8", "3/8 rows 181-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1",
                             "8/8 rows 480-479 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1",
                             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1 extra",
                             "3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdeg/1",
                             "3/8 rows 180-239 of 640x480; spp 4; cpu reference"}) {
        EXPECT_FALSE(parseTileStamp(text)) << text;
    }
    EXPECT_TRUE(parseTileStamp("3/8 rows 180-239 of 640x480; spp 4; cpu reference; scene 0123456789abcdef/1"));
}

TEST(TileStamp, SceneIdentityIsTheTextsHashAndSize) {
    EXPECT_EQ(sceneTextIdentity("{}"), sceneTextIdentity(std::string("{}")));
    EXPECT_NE(sceneTextIdentity("{} "), sceneTextIdentity("{}"));
    EXPECT_EQ(sceneTextIdentity("abc").substr(16), "/3");
}

}  // namespace
}  // namespace hexray
