// `hexray merge` on pieces that declare more than the renderer makes: refused by what their
// stamps and headers say, before anything is allocated from those sizes.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "image/image_row_writer.h"
#include "fuzz/piece_judgement.h"
#include "image/image_format.h"
#include "support/address_space_limit.h"
#include "support/temporary_directory_test.h"
#include "support/test_paths.h"
#include "strip/strip_merge.h"
#include "strip/strip_stamp.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = "0123456789abcdef/1";

class StripMergeTest : public test::TemporaryDirectoryTest {
protected:
    // A PNG piece of `stamp`'s strip, every byte `level`, stamped as `hexray render --strip` does.
    std::string writePiece(const std::string& name, const StripStamp& stamp, std::uint8_t level = 0) const {
        const std::string path = (dir_ / name).string();
        const std::string text = formatStripStamp(stamp);
        ImageRowWriter writer(path, ImageFormat::Png, stamp.width, stamp.rows().count, Encoding::Srgb, {},
                              {{kStripStampKey, text}}, DigestNote{kStripDigestKey, text});
        const std::vector<std::uint8_t> row(std::size_t(stamp.width) * 3, level);
        for (std::uint32_t y = 0; y < stamp.rows().count; ++y) {
            writer.writeEncoded(row);
        }
        writer.finish();
        return path;
    }

    // Merging `pieces` is refused with `message`, within 256 MiB of new address space, leaving
    // no output.
    void expectRefusedWithinMemory(const std::vector<std::string>& pieces, const std::string& message) const {
        const std::string output = (dir_ / "merged.png").string();
        try {
            const test::AddressSpaceLimit limit(std::size_t{256} << 20);
            mergeStrips(output, pieces);
            ADD_FAILURE() << "merged";
        } catch (const StripError& error) {
            EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
        } catch (const std::bad_alloc&) {
            ADD_FAILURE() << "allocated more than 256 MiB from what the piece declares";
        }
        EXPECT_FALSE(fs::exists(output));
    }
};

TEST_F(StripMergeTest, AStampDeclaringMoreStripsThanTheRendererMakesIsRefusedBeforeAllocation) {
    const std::string piece = writePiece("a.png", {{0, 100000000}, 67, 100000000, 1, "cpu reference", kScene, "0.1.0"});
    expectRefusedWithinMemory({piece},
                              "a.png: its stamp declares a 67x100000000 image, larger than hexray renders "
                              "(at most 16384x16384)");
}

TEST_F(StripMergeTest, APieceWiderThanTheRendererMakesIsRefusedBeforeAllocation) {
    const std::string piece = writePiece("wide.png", {{0, 1}, 5000000, 32, 1, "cpu reference", kScene, "0.1.0"});
    expectRefusedWithinMemory({piece},
                              "wide.png: its stamp declares a 5000000x32 image, larger than hexray renders "
                              "(at most 16384x16384)");
}

TEST_F(StripMergeTest, AnOutputLargerThanTheRendererMakesIsRefused) {
    const std::string piece = writePiece("big.png", {{0, 20000}, 20000, 20000, 1, "cpu reference", kScene, "0.1.0"});
    expectRefusedWithinMemory({piece},
                              "big.png: its stamp declares a 20000x20000 image, larger than hexray renders "
                              "(at most 16384x16384)");
}

// The pieces are read from the files opened and checked, whatever is at their paths by then.
TEST_F(StripMergeTest, APieceReplacedAfterTheCheckDoesNotChangeTheImage) {
    const StripStamp top{{0, 2}, 5, 4, 1, "cpu reference", kScene, "0.1.0"};
    StripStamp bottom = top;
    bottom.strip.index = 1;
    const std::vector<std::string> pieces = {writePiece("a.png", top, 10), writePiece("b.png", bottom, 20)};
    writePiece("other-b.png", bottom, 200);  // a valid piece of the same strip, other pixels
    std::vector<StripPiece> strips = openPieces(pieces, ImageFormat::Png);
    fs::rename(dir_ / "other-b.png", dir_ / "b.png");
    fs::remove(dir_ / "a.png");
    mergePieces((dir_ / "merged.png").string(), strips);
    std::vector<std::uint8_t> expected(5 * 2 * 3, 10);
    expected.resize(5 * 4 * 3, 20);
    EXPECT_EQ(readPng(dir_ / "merged.png").bytes, expected);
}

// The piece fuzzer's seeds (tests/fuzz/pieces/) are pieces merge verifies; with any single bit of
// them flipped, merge refuses the piece or reads exactly the same pixels.
TEST_F(StripMergeTest, EverySingleBitFlipOfAPieceIsRefusedOrChangesNoPixel) {
    for (const auto& entry : fs::directory_iterator(test::sourcePath("tests/fuzz/pieces"))) {
        const std::string seed = entry.path().string();
        const ImageFormat format = *imageFormatFor(seed);
        const test::PieceVerdict original = test::judgePiece(ReadOnlyFile(seed), format);
        ASSERT_TRUE(original.verified) << seed << ": " << original.refusal;
        std::ifstream in(seed, std::ios::binary);
        std::string bytes(std::istreambuf_iterator<char>(in), {});
        const std::string flipped = (dir_ / entry.path().filename()).string();
        int refused = 0;
        for (std::size_t bit = 0; bit < bytes.size() * 8; ++bit) {
            bytes[bit / 8] = char(bytes[bit / 8] ^ (1 << bit % 8));
            std::ofstream(flipped, std::ios::binary | std::ios::trunc) << bytes;
            bytes[bit / 8] = char(bytes[bit / 8] ^ (1 << bit % 8));
            const test::PieceVerdict verdict = test::judgePiece(ReadOnlyFile(flipped), format);
            ASSERT_FALSE(verdict.violation) << seed << " bit " << bit << ": " << *verdict.violation;
            if (verdict.verified) {
                ASSERT_EQ(verdict.pixels, original.pixels) << seed << ": bit " << bit << " changed the pixels";
            }
            refused += !verdict.verified;
        }
        EXPECT_GT(refused, 0) << seed;
    }
}

}  // namespace
}  // namespace hexray
