// `render --strip I/N` and `hexray merge`: the merged pieces are the single render, pixel for
// pixel, on both backends and with anti-aliasing; pieces that do not make one image are refused.

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/exr_io.h"
#include "image/exr_row_reader.h"
#include "image/exr_row_writer.h"
#include "image/image_io.h"
#include "image/pixel_digest.h"
#include "image/png_row_reader.h"
#include "io/read_only_file.h"
#include "support/png_rewrite.h"
#include "strip/strip_stamp.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

// An odd size, so the strips differ in height; several samples a pixel.
constexpr const char* kImage = " --width 67 --height 53 --spp 4";

class StripCliTest : public CliTest {
protected:
    // Renders the scene whole and in `strips` pieces (in reverse order, to show order does not
    // matter), merges them, and returns the merge's run.
    RunResult renderAndMerge(const std::string& options, std::uint32_t strips, const std::string& extension) {
        const std::string render = "render " + scene("spheres-and-lights.json") + kImage + " " + options;
        EXPECT_EQ(hexray(render + " -o whole" + extension).exitCode, 0);
        std::string pieces;
        for (std::uint32_t i = strips; i-- > 0;) {
            const std::string piece = "piece-" + std::to_string(i) + extension;
            const RunResult run =
                hexray(render + " --strip " + std::to_string(i) + "/" + std::to_string(strips) + " -o " + piece);
            EXPECT_EQ(run.exitCode, 0) << run.err;
            pieces += " " + piece;
        }
        return hexray("merge merged" + extension + pieces);
    }

    // Renders the CPU reference's `strips` strips of a small image as piece-I.EXTENSION.
    void renderPieces(std::uint32_t strips, const std::string& extension) {
        for (std::uint32_t i = 0; i < strips; ++i) {
            const RunResult run =
                hexray("render " + scene("spheres-and-lights.json") + kImage + " --backend cpu --strip " +
                       std::to_string(i) + "/" + std::to_string(strips) + " -o piece-" + std::to_string(i) + extension);
            ASSERT_EQ(run.exitCode, 0) << run.err;
        }
    }

    // What `hexray --version` says of this build: "0.1.0 (git ...)".
    std::string hexrayVersion() const {
        const std::string out = hexray("--version").out;
        return out.substr(7, out.find('\n') - 7);
    }

    // Merges piece-0..2.png into merged.png: refused, naming `message`, with nothing written.
    void expectRefusal(const std::string& message) {
        const RunResult run = hexray("merge merged.png piece-0.png piece-1.png piece-2.png");
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
        EXPECT_FALSE(fs::exists(dir_ / "merged.png"));
    }
};

TEST_F(StripCliTest, MergedGpuStripsAreTheSingleRenderPixelForPixel) {
    const RunResult merge = renderAndMerge("--backend gpu", 5, ".png");
    ASSERT_EQ(merge.exitCode, 0) << merge.err;
    EXPECT_NE(merge.out.find("wrote merged.png (67x53) from 5 pieces"), std::string::npos) << merge.out;
    EXPECT_EQ(readPng(dir_ / "merged.png").bytes, readPng(dir_ / "whole.png").bytes);
}

// Strips of 10 or 11 rows start inside the culling's 8-row screen tiles, whose kernels leave out
// what their own rows cannot see.
TEST_F(StripCliTest, MergedGpuStripsWithCullingAreTheSingleRenderPixelForPixel) {
    const RunResult merge = renderAndMerge("--backend gpu --culling on", 5, ".png");
    ASSERT_EQ(merge.exitCode, 0) << merge.err;
    EXPECT_EQ(readPng(dir_ / "merged.png").bytes, readPng(dir_ / "whole.png").bytes);
}

TEST_F(StripCliTest, MergedCpuStripsAreTheSingleRenderPixelForPixel) {
    const RunResult merge = renderAndMerge("--backend cpu", 4, ".png");
    ASSERT_EQ(merge.exitCode, 0) << merge.err;
    EXPECT_EQ(readPng(dir_ / "merged.png").bytes, readPng(dir_ / "whole.png").bytes);
}

TEST_F(StripCliTest, MergedOpenExrStripsAreTheSingleRenderValueForValue) {
    const RunResult merge = renderAndMerge("--backend gpu", 3, ".exr");
    ASSERT_EQ(merge.exitCode, 0) << merge.err;
    const ExrImage merged = readExr(dir_ / "merged.exr");
    const ExrImage whole = readExr(dir_ / "whole.exr");
    EXPECT_EQ(merged.width, 67u);
    EXPECT_EQ(merged.height, 53u);
    EXPECT_EQ(merged.channels, whole.channels);
}

TEST_F(StripCliTest, APieceRecordsItsPlaceInATextChunk) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + kImage + " --backend cpu --strip 2/5");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("wrote lecture-demo.strip-2-of-5.png (rows 21-30 of 67x53) — cpu reference"),
              std::string::npos)
        << run.out;
    const ReadOnlyFile file((dir_ / "lecture-demo.strip-2-of-5.png").string());
    PngRowReader piece(file);
    EXPECT_EQ(piece.width(), 67u);
    EXPECT_EQ(piece.height(), 10u);  // rows floor(2*53/5) = 21 to floor(3*53/5) - 1 = 30
    const std::string text = piece.text(kStripStampKey).value_or("");
    const std::string sceneText = readFile(test::sourcePath("scenes/lecture-demo.json"));
    EXPECT_EQ(text, "2/5 rows 21-30 of 67x53; spp 4; cpu reference; scene " + sceneTextIdentity(sceneText) +
                        "; hexray " + hexrayVersion())
        << text;
    // After the pixels, the SHA-256 of the stamp (and a NUL) and the pixels.
    std::vector<std::uint8_t> rows(67 * 10 * 3);
    piece.readRows(rows);
    PixelDigest digest(text);
    digest.addRgb8Rows(rows);
    EXPECT_EQ(piece.textAfterPixels(kStripDigestKey), digest.hex());
}

TEST_F(StripCliTest, MergeRefusesMissingOverlappingAndMismatchedPiecesNamingThem) {
    const std::string render = "render " + scene("lecture-demo.json") + kImage + " --backend cpu";
    for (const char* strip : {"0/3", "1/3", "2/3"}) {
        ASSERT_EQ(hexray(render + " --strip " + strip).exitCode, 0);
    }
    ASSERT_EQ(hexray("render " + scene("lecture-demo.json") +
                     " --width 67 --height 53 --spp 2 --backend cpu "
                     "--strip 1/3 -o other-spp.png")
                  .exitCode,
              0);
    ASSERT_EQ(hexray(render + " --strip 1/4 -o other-count.png").exitCode, 0);
    ASSERT_EQ(hexray(render + " --strip 1/3 -o again.png").exitCode, 0);
    ASSERT_EQ(hexray(render + " -o whole.png").exitCode, 0);
    const std::string first = " lecture-demo.strip-0-of-3.png";
    const std::string last = " lecture-demo.strip-2-of-3.png";
    const std::string middle = " lecture-demo.strip-1-of-3.png";
    const struct {
        std::string pieces;
        std::string message;
    } cases[] = {
        {first + last, "missing strip 1/3, rows 17-34 of the image lecture-demo.strip-0-of-3.png belongs to"},
        {first + middle + " again.png" + last,
         "again.png: overlaps lecture-demo.strip-1-of-3.png (both are strip 1/3, rows 17-34)"},
        {first + middle + middle + last, "lecture-demo.strip-1-of-3.png: given twice"},
        {first + " other-spp.png" + last,
         "other-spp.png: a strip of another image than lecture-demo.strip-0-of-3.png: spp 2 (not 4)"},
        {first + " other-count.png" + last,
         "other-count.png: a strip of another image than "
         "lecture-demo.strip-0-of-3.png: strip count 4 (not 3)"},
        {first + " whole.png" + last, "whole.png: not a piece of a render in strips (no hexray-strip stamp"},
        {first + " nothing.png" + last, "nothing.png: cannot open: No such file or directory"},
    };
    for (const auto& [pieces, message] : cases) {
        const RunResult run = hexray("merge merged.png" + pieces);
        EXPECT_EQ(run.exitCode, 2) << pieces << "\n" << run.err;
        EXPECT_NE(run.err.find(message), std::string::npos) << pieces << "\n" << run.err;
        EXPECT_FALSE(fs::exists(dir_ / "merged.png")) << pieces;
    }
}

TEST_F(StripCliTest, MergeRefusesAnOutputThatIsAPieceAndAPieceOfAnotherFormat) {
    const std::string render = "render " + scene("lecture-demo.json") + kImage + " --backend cpu";
    ASSERT_EQ(hexray(render + " --strip 0/2 -o a.png").exitCode, 0);
    ASSERT_EQ(hexray(render + " --strip 1/2 -o b.exr").exitCode, 0);
    RunResult run = hexray("merge a.png a.png b.exr");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("the output a.png: the same file as the piece a.png"), std::string::npos) << run.err;
    run = hexray("merge m.png a.png b.exr");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("b.exr: not a PNG file (.png), as the merged image is"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "m.png"));
}

// What a PNG optimiser may write: the same pixels and text chunks, interlaced. Read as rows, the
// passes would be a scrambled image.
TEST_F(StripCliTest, AnInterlacedPieceIsRefusedByName) {
    renderPieces(3, ".png");
    test::encodePng(dir_ / "piece-1.png", test::decodePng(dir_ / "piece-1.png"), true);
    expectRefusal("piece-1.png: an interlaced PNG, which merge does not read");
}

// A piece re-encoded as a valid PNG with its stamp, one pixel changed: only its checksum tells.
TEST_F(StripCliTest, APieceWhosePixelsChangedIsRefused) {
    renderPieces(3, ".png");
    test::DecodedPng piece = test::decodePng(dir_ / "piece-1.png");
    piece.rgb[100] ^= 1;
    test::encodePng(dir_ / "piece-1.png", piece);
    expectRefusal("piece-1.png: its pixels are not the ones it was rendered with");
}

TEST_F(StripCliTest, AnOpenExrPieceWhoseValuesChangedIsRefused) {
    renderPieces(2, ".exr");
    ExrImage piece = readExr(dir_ / "piece-1.exr");
    std::vector<ImageNote> notes;
    {
        const ExrRowReader reader(dir_ / "piece-1.exr");
        for (const char* key : {kStripStampKey, "hexray-strip-sha256"}) {
            if (const std::optional<std::string> text = reader.stringAttribute(key)) {
                notes.push_back({key, *text});
            }
        }
    }
    piece.channels["G"][7] = std::nextafter(piece.channels["G"][7], 2.0f);
    ExrRowWriter writer(dir_ / "piece-1.exr", piece.width, piece.height, {"R", "G", "B"}, notes);
    writer.writeRows(piece.height, {piece.channels["R"], piece.channels["G"], piece.channels["B"]});
    writer.finish();
    const RunResult run = hexray("merge merged.exr piece-0.exr piece-1.exr");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("piece-1.exr: its pixels are not the ones it was rendered with"), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "merged.exr"));
}

// Another build may render other pixels: its pieces are not merged with this one's. The stamp is
// rewritten in its own format, as another build writes it.
TEST_F(StripCliTest, PiecesOfTwoVersionsAreRefusedNamingBoth) {
    const std::string ours = hexrayVersion();
    const std::string ourRevision = ours.substr(0, ours.find(" (git ")) + " (git 0000000dead0)";
    for (const std::string& theirs : {std::string("0.0.9 (git 0123456789ab)"), ourRevision}) {
        renderPieces(3, ".png");
        test::DecodedPng piece = test::decodePng(dir_ / "piece-1.png");
        std::string stamp = piece.text(kStripStampKey);
        stamp = stamp.substr(0, stamp.find("; hexray ")) + "; hexray " + theirs;
        ASSERT_TRUE(parseStripStamp(stamp)) << stamp;
        piece.setText(kStripStampKey, stamp);
        test::encodePng(dir_ / "piece-1.png", piece);
        expectRefusal("piece-1.png: rendered by hexray " + theirs + ", but piece-0.png by hexray " + ours +
                      ": pieces of two builds are not merged (another build may render other pixels); render "
                      "them again with one");
    }
}

// Every piece stays open from the check to the copy: more pieces than the hard limit on open
// files are refused up front; a soft limit below it is raised.
TEST_F(StripCliTest, MorePiecesThanFilesMayBeOpenAreRefusedUpFront) {
    const RunResult render = shell("for i in $(seq 0 29); do \"$HEXRAY\" render " + scene("lecture-demo.json") +
                                   " --width 8 --height 30 --backend cpu --strip $i/30 -o p-$i.png || exit 1; done");
    ASSERT_EQ(render.exitCode, 0) << render.err;
    RunResult run = shell("ulimit -n 20 && \"$HEXRAY\" merge merged.png p-*.png");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("30 pieces, but this process may have only 20 files open (ulimit -n)"), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "merged.png"));
    run = shell("ulimit -S -n 20 && \"$HEXRAY\" merge merged.png p-*.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(fs::exists(dir_ / "merged.png"));
}

TEST_F(StripCliTest, AStripSpecificationOutsideItsRangeIsExitCode2) {
    for (const char* strip : {"3/3", "-1/3", "1/0", "1", "a/b", "1/20000"}) {
        const RunResult run = hexray("render " + scene("lecture-demo.json") + " --strip " + strip);
        EXPECT_EQ(run.exitCode, 2) << strip;
        EXPECT_NE(
            run.err.find("--strip: must be I/N, strip I of N, with 0 <= I < N <= 16384 (got " + std::string(strip)),
            std::string::npos)
            << run.err;
    }
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " --width 8 --height 4 --strip 0/5");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--strip 0/5: the image has 4 rows, so at most 4 strips"), std::string::npos) << run.err;
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

}  // namespace
}  // namespace hexray
