// The readers of `hexray merge`'s pieces, from an open file: every form of PNG either read as
// the same 8-bit RGB or refused by name (interlaced), and the R, G, B floats of an OpenEXR file
// read in bands of any height, with what hexray does not write refused by name.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>
#include <spng.h>

#include "image/exr_rgb_row_reader.h"
#include "image/exr_row_writer.h"
#include "image/image_io.h"
#include "image/png_row_reader.h"
#include "io/read_only_file.h"
#include "support/png_rewrite.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using PieceReadersTest = test::TemporaryDirectoryTest;

constexpr std::uint32_t kWidth = 4;
constexpr std::uint32_t kHeight = 3;

// A kWidth x kHeight PNG of `colorType` and `bitDepth` whose bytes are `data` (and `palette`).
void writePngForm(const fs::path& path, std::uint8_t colorType, std::uint8_t bitDepth,
                  const std::vector<std::uint8_t>& data, const std::vector<spng_plte_entry>& palette = {}) {
    test::OpenFile file(std::fopen(path.c_str(), "wb"), std::fclose);
    test::SpngContext context(spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free);
    test::checkSpng(spng_set_png_file(context.get(), file.get()), "file");
    spng_ihdr header{kWidth, kHeight, bitDepth, colorType, 0, 0, 0};
    test::checkSpng(spng_set_ihdr(context.get(), &header), "ihdr");
    if (!palette.empty()) {
        spng_plte plte{};
        plte.n_entries = std::uint32_t(palette.size());
        std::copy(palette.begin(), palette.end(), plte.entries);
        test::checkSpng(spng_set_plte(context.get(), &plte), "plte");
    }
    test::checkSpng(spng_encode_image(context.get(), data.data(), data.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE),
                    "encode");
}

std::vector<std::uint8_t> readAllRows(const fs::path& path) {
    const ReadOnlyFile file(path.string());
    PngRowReader reader(file);
    EXPECT_EQ(reader.width(), kWidth);
    EXPECT_EQ(reader.height(), kHeight);
    std::vector<std::uint8_t> rows(kWidth * kHeight * 3);
    reader.readRows(std::span(rows).first(kWidth * 3));
    reader.readRows(std::span(rows).subspan(kWidth * 3));
    return rows;
}

// Grey levels 0, 20, ..., 220, as the RGB a reader must see.
std::vector<std::uint8_t> greyRgb() {
    std::vector<std::uint8_t> rgb;
    for (std::uint8_t i = 0; i < kWidth * kHeight; ++i)
        rgb.insert(rgb.end(), 3, std::uint8_t(20 * i));
    return rgb;
}

// Each pixel's value `bytes`, as one sample of each of `samples` channels (16 bits: v * 257, big-endian).
std::vector<std::uint8_t> samplesOf(const std::vector<std::uint8_t>& values, int channels, bool sixteenBits,
                                    int alphaChannel = -1) {
    std::vector<std::uint8_t> data;
    for (std::size_t i = 0; i < values.size(); i += std::size_t(channels == 2 || channels == 1 ? 3 : 3)) {
        for (int c = 0; c < channels; ++c) {
            const std::uint8_t value = c == alphaChannel ? 255 : values[i + std::size_t(channels >= 3 ? c : 0)];
            data.push_back(value);
            if (sixteenBits)
                data.push_back(value);  // v * 257 = v in both bytes
        }
    }
    return data;
}

TEST_F(PieceReadersTest, EveryNonInterlacedPngFormIsReadAsTheSame8BitRgb) {
    const std::vector<std::uint8_t> grey = greyRgb();
    std::vector<std::uint8_t> colour = grey;
    for (std::size_t i = 0; i < colour.size(); ++i)
        colour[i] = std::uint8_t(colour[i] + 7 * (i % 3));
    const struct {
        const char* form;
        std::uint8_t colorType;
        std::uint8_t bitDepth;
        std::vector<std::uint8_t> data;
        std::vector<std::uint8_t> rgb;
    } forms[] = {
        {"rgb8", SPNG_COLOR_TYPE_TRUECOLOR, 8, samplesOf(colour, 3, false), colour},
        {"rgb16", SPNG_COLOR_TYPE_TRUECOLOR, 16, samplesOf(colour, 3, true), colour},
        {"rgba8", SPNG_COLOR_TYPE_TRUECOLOR_ALPHA, 8, samplesOf(colour, 4, false, 3), colour},
        {"rgba16", SPNG_COLOR_TYPE_TRUECOLOR_ALPHA, 16, samplesOf(colour, 4, true, 3), colour},
        {"grey8", SPNG_COLOR_TYPE_GRAYSCALE, 8, samplesOf(grey, 1, false), grey},
        {"grey16", SPNG_COLOR_TYPE_GRAYSCALE, 16, samplesOf(grey, 1, true), grey},
        {"greyalpha8", SPNG_COLOR_TYPE_GRAYSCALE_ALPHA, 8, samplesOf(grey, 2, false, 1), grey},
    };
    for (const auto& form : forms) {
        writePngForm(dir_ / "form.png", form.colorType, form.bitDepth, form.data);
        EXPECT_EQ(readAllRows(dir_ / "form.png"), form.rgb) << form.form;
    }
    // A palette: pixel i is entry i of 12.
    std::vector<spng_plte_entry> palette;
    std::vector<std::uint8_t> indices;
    for (std::uint8_t i = 0; i < kWidth * kHeight; ++i) {
        palette.push_back({colour[3 * i], colour[3 * i + 1], colour[3 * i + 2], 255});
        indices.push_back(i);
    }
    writePngForm(dir_ / "palette.png", SPNG_COLOR_TYPE_INDEXED, 8, indices, palette);
    EXPECT_EQ(readAllRows(dir_ / "palette.png"), colour);
    // One bit a pixel: black and white.
    writePngForm(dir_ / "bits.png", SPNG_COLOR_TYPE_GRAYSCALE, 1, {0b10100000, 0b01010000, 0b11110000});
    std::vector<std::uint8_t> bits;
    for (const int bit : {1, 0, 1, 0, 0, 1, 0, 1, 1, 1, 1, 1})
        bits.insert(bits.end(), 3, std::uint8_t(bit * 255));
    EXPECT_EQ(readAllRows(dir_ / "bits.png"), bits);
}

TEST_F(PieceReadersTest, AnInterlacedPngIsRefusedByName) {
    test::encodePng(dir_ / "i.png", {kWidth, kHeight, greyRgb(), {}}, true);
    const ReadOnlyFile file((dir_ / "i.png").string());
    try {
        PngRowReader reader(file);
        FAIL() << "read an interlaced PNG";
    } catch (const ImageIoError& error) {
        EXPECT_NE(std::string(error.what()).find("i.png: an interlaced PNG, which merge does not read"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(PieceReadersTest, TextsBeforeAndAfterThePixelsAreToldApart) {
    test::encodePng(dir_ / "t.png", {kWidth, kHeight, greyRgb(), {{"a", "before", false}, {"b", "after", true}}});
    const ReadOnlyFile file((dir_ / "t.png").string());
    PngRowReader reader(file);
    EXPECT_EQ(reader.text("a"), "before");
    EXPECT_EQ(reader.text("b"), std::nullopt);
    std::vector<std::uint8_t> rows(kWidth * kHeight * 3);
    reader.readRows(rows);
    EXPECT_EQ(reader.textAfterPixels("b"), "after");
    EXPECT_EQ(reader.textAfterPixels("a"), std::nullopt);
}

// 40 rows: three ZIP chunks of 16 rows, the last short, read in bands of 7.
TEST_F(PieceReadersTest, OpenExrRgbIsReadInBandsOfAnyHeightIgnoringOtherChannels) {
    constexpr std::uint32_t width = 3;
    constexpr std::uint32_t height = 40;
    std::vector<std::vector<float>> planes(4, std::vector<float>(width * height));
    for (std::size_t c = 0; c < planes.size(); ++c) {
        for (std::size_t i = 0; i < planes[c].size(); ++i)
            planes[c][i] = float(c) * 1000.0f + float(i) * 0.5f;
    }
    ExrRowWriter writer(dir_ / "a.exr", width, height, {"R", "G", "B", "A"}, {{"note", "text"}});
    writer.writeRows(height, {planes[0], planes[1], planes[2], planes[3]});
    writer.finish();
    const ReadOnlyFile file((dir_ / "a.exr").string());
    ExrRgbRowReader reader(file);
    EXPECT_EQ(reader.width(), width);
    EXPECT_EQ(reader.height(), height);
    EXPECT_EQ(reader.stringAttribute("note"), "text");
    EXPECT_EQ(reader.stringAttribute("none"), std::nullopt);
    std::vector<std::vector<float>> read(3);
    for (std::uint32_t done = 0; done < height; done += 7) {
        const std::uint32_t rows = std::min(7u, height - done);
        std::vector<float> r(rows * width), g(rows * width), b(rows * width);
        reader.readRows(rows, r, g, b);
        read[0].insert(read[0].end(), r.begin(), r.end());
        read[1].insert(read[1].end(), g.begin(), g.end());
        read[2].insert(read[2].end(), b.begin(), b.end());
    }
    for (std::size_t c = 0; c < 3; ++c)
        EXPECT_EQ(read[c], planes[c]) << c;
    std::vector<float> one(width);
    EXPECT_THROW(reader.readRows(1, one, one, one), ImageIoError);
}

// An OpenEXR file of `width` x 2 written by OpenEXR's C++ interface, as `adjust` makes its header.
void writeExrWith(const fs::path& path, int width, const std::function<void(Imf::Header&)>& adjust) {
    Imf::Header header(width, 2);
    for (const char* name : {"R", "G", "B"})
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    adjust(header);
    std::vector<float> values(std::size_t(width) * 2, 0.25f);
    Imf::FrameBuffer frame;
    for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
        if (channel.channel().type != Imf::FLOAT)
            continue;  // written as zeros
        frame.insert(channel.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                                sizeof(float) * std::size_t(width), channel.channel().xSampling,
                                                channel.channel().ySampling));
    }
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(2);
}

TEST_F(PieceReadersTest, OpenExrFormsHexrayDoesNotWriteAreRefusedByName) {
    const struct {
        const char* name;
        std::function<void(Imf::Header&)> adjust;
        int width;
        std::string message;
    } cases[] = {
        {"piz.exr", [](Imf::Header& h) { h.compression() = Imf::PIZ_COMPRESSION; }, 4,
         "piz.exr: an OpenEXR file compressed with PIZ, which merge does not read"},
        {"half.exr", [](Imf::Header& h) { h.channels()["G"].type = Imf::HALF; }, 4,
         "half.exr: channel G is not of 32-bit floats"},
        {"nored.exr",
         [](Imf::Header& h) {
             h.channels() = Imf::ChannelList();
             h.channels().insert("G", Imf::Channel(Imf::FLOAT));
         },
         4, "nored.exr: not an image hexray wrote (no channel R)"},
        {"sub.exr", [](Imf::Header& h) { h.channels().insert("Y", Imf::Channel(Imf::FLOAT, 2, 2)); }, 4,
         "sub.exr: channel Y is subsampled"},
        {"wide.exr", [](Imf::Header&) {}, 16385, "wide.exr: cannot read OpenEXR"},
    };
    for (const auto& [name, adjust, width, message] : cases) {
        writeExrWith(dir_ / name, width, adjust);
        const ReadOnlyFile file((dir_ / name).string());
        try {
            ExrRgbRowReader reader(file);
            ADD_FAILURE() << name << " read";
        } catch (const ImageIoError& error) {
            EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
        }
    }
}

}  // namespace
}  // namespace hexray
