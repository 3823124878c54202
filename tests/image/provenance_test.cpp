// The provenance record (image/provenance.h): read back from PNG and OpenEXR files exactly as
// written, without changing a pixel; a file without one reads empty; a malformed one is refused
// naming the file and the key.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/exr_io.h"
#include "image/image_io.h"
#include "image/image_row_writer.h"
#include "image/provenance.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using ProvenanceTest = test::TemporaryDirectoryTest;

Provenance fullRecord() {
    return Provenance{"0.1.0",  "9317900a2b4c",
                      "render", "5f0c3e2a9b1d4c77/1187",
                      "gpu",    "llvmpipe (LLVM 15.0.6, 256 bits)",
                      "f32",    4,
                      5,        3};
}

// A 5x3 image of distinct values through ImageRowWriter in `format`, recording `provenance`.
void writeImage(const fs::path& path, ImageFormat format, const Provenance& provenance) {
    Image image(5, 3);
    for (std::uint32_t i = 0; i < 15; ++i) {
        image.pixels[i] = {float(i) / 15.0f, 0.5f, 1.0f - float(i) / 20.0f};
    }
    ImageRowWriter writer(path, format, 5, 3, Encoding::Srgb, provenance);
    writer.writeLinear(image);
    writer.finish();
}

TEST_F(ProvenanceTest, APngReadsBackItsRecordAndTheSamePixels) {
    writeImage(dir_ / "with.png", ImageFormat::Png, fullRecord());
    writeImage(dir_ / "without.png", ImageFormat::Png, {});
    EXPECT_EQ(readProvenance(dir_ / "with.png"), fullRecord());
    EXPECT_EQ(readPng(dir_ / "with.png").bytes, readPng(dir_ / "without.png").bytes);
}

TEST_F(ProvenanceTest, AnOpenExrFileReadsBackItsRecordAndTheSameValues) {
    writeImage(dir_ / "with.exr", ImageFormat::Exr, fullRecord());
    writeImage(dir_ / "without.exr", ImageFormat::Exr, {});
    EXPECT_EQ(readProvenance(dir_ / "with.exr"), fullRecord());
    EXPECT_EQ(readExr(dir_ / "with.exr").channels, readExr(dir_ / "without.exr").channels);
}

// Told apart by their first bytes: a PNG named .exr is read as the PNG it is.
TEST_F(ProvenanceTest, TheFormatIsReadFromTheFileNotItsName) {
    writeImage(dir_ / "a.png", ImageFormat::Png, fullRecord());
    fs::rename(dir_ / "a.png", dir_ / "a.exr");
    EXPECT_EQ(readProvenance(dir_ / "a.exr"), fullRecord());
}

TEST_F(ProvenanceTest, AFileWithoutARecordReadsEmpty) {
    writePng(dir_ / "plain.png", Rgb8Image{1, 1, {1, 2, 3}});
    writeExr(dir_ / "plain.exr", 1, 1, {{"Y", {0.5f}}});
    EXPECT_TRUE(readProvenance(dir_ / "plain.png").empty());
    EXPECT_TRUE(readProvenance(dir_ / "plain.exr").empty());
}

TEST(Provenance, OnlyTheFieldsFilledInAreRecordedUnderThePrefix) {
    Provenance partial;
    partial.version = "0.1.0";
    partial.samplesPerPixel = 2;
    partial.width = 7;  // no height: no resolution
    const std::vector<ImageNote> notes = partial.notes();
    ASSERT_EQ(notes.size(), 2u);
    EXPECT_EQ(notes[0].key, "hexray:version");
    EXPECT_EQ(notes[0].text, "0.1.0");
    EXPECT_EQ(notes[1].key, "hexray:spp");
    EXPECT_EQ(notes[1].text, "2");
    EXPECT_TRUE(Provenance{}.empty());
    EXPECT_EQ(fullRecord().describe(),
              "hexray:version 0.1.0\nhexray:git-revision 9317900a2b4c\nhexray:image render\n"
              "hexray:scene 5f0c3e2a9b1d4c77/1187\nhexray:backend gpu\nhexray:device llvmpipe (LLVM 15.0.6, 256 "
              "bits)\nhexray:precision f32\nhexray:spp 4\nhexray:resolution 5x3\n");
    for (const ImageNote& note : fullRecord().notes()) {
        EXPECT_EQ(note.key.rfind(kProvenanceKeyPrefix, 0), 0u) << note.key;
    }
}

TEST(Provenance, KeysOfOtherProgramsAreIgnored) {
    const Provenance read =
        provenanceFromNotes({{"Software", "GIMP"}, {"hexray:spp", "8"}, {"hexray:future", "x"}}, "a.png");
    Provenance expected;
    expected.samplesPerPixel = 8;
    EXPECT_EQ(read, expected);
}

TEST(Provenance, AMalformedRecordIsRefusedNamingTheFileAndTheKey) {
    const struct {
        std::vector<ImageNote> notes;
        std::string message;
    } cases[] = {
        {{{"hexray:spp", "four"}}, "a.png: its hexray:spp is not a positive decimal number (\"four\")"},
        {{{"hexray:spp", "0"}}, "a.png: its hexray:spp is not a positive decimal number"},
        {{{"hexray:spp", "99999999999"}}, "a.png: its hexray:spp is not a positive decimal number"},
        {{{"hexray:resolution", "640"}}, "a.png: its hexray:resolution is not WIDTHxHEIGHT (\"640\")"},
        {{{"hexray:resolution", "640x-1"}}, "a.png: its hexray:resolution is not a positive decimal number"},
        {{{"hexray:device", "gpu\x1b[2J"}}, "a.png: its hexray:device is not text a record holds (\"gpu\\x1b[2J\")"},
        {{{"hexray:scene", std::string(2000, 'a')}}, "a.png: its hexray:scene is not text a record holds"},
        {{{"hexray:backend", "gpu"}, {"hexray:backend", "cpu"}}, "a.png: its hexray:backend is recorded twice"},
    };
    for (const auto& [notes, message] : cases) {
        try {
            provenanceFromNotes(notes, "a.png");
            ADD_FAILURE() << message;
        } catch (const ImageIoError& error) {
            EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
        }
    }
}

TEST_F(ProvenanceTest, AMalformedRecordInAFileIsRefusedNamingIt) {
    const fs::path path = dir_ / "bad.png";
    PngRowWriter writer(path, 1, 1, {{"hexray:spp", "-3"}});
    writer.writeRows(std::vector<std::uint8_t>{1, 2, 3});
    writer.finish();
    try {
        readProvenance(path);
        ADD_FAILURE() << "read";
    } catch (const ImageIoError& error) {
        EXPECT_NE(std::string(error.what()).find(path.string() + ": its hexray:spp is not a positive decimal number"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(ProvenanceTest, AFileOfNeitherFormatIsRefusedNamingIt) {
    std::ofstream(dir_ / "notes.png") << "not an image";
    for (const fs::path& path : {dir_ / "notes.png", dir_ / "missing.exr"}) {
        try {
            readProvenance(path);
            ADD_FAILURE() << path;
        } catch (const ImageIoError& error) {
            EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
        }
    }
}

}  // namespace
}  // namespace hexray
