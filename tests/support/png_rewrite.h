#pragma once
// PNGs taken apart and put together again through libspng, as other tools would re-encode a
// piece of a render in strips: its pixels decoded to 8-bit RGB and its text chunks kept in their
// places (before or after the pixels), then encoded again, perhaps interlaced (Adam7, as PNG
// optimisers may) or with other pixels or texts.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <spng.h>

namespace hexray::test {

struct PngText {
    std::string keyword;
    std::string text;
    bool afterPixels = false;
};

struct DecodedPng {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgb;  // 3 bytes a pixel
    std::vector<PngText> texts;

    // The text of the chunk `keyword` (the first), or "" when there is none.
    std::string text(const std::string& keyword) const {
        for (const PngText& chunk : texts) {
            if (chunk.keyword == keyword)
                return chunk.text;
        }
        return "";
    }
    void setText(const std::string& keyword, const std::string& text) {
        for (PngText& chunk : texts) {
            if (chunk.keyword == keyword)
                chunk.text = text;
        }
    }
};

using SpngContext = std::unique_ptr<spng_ctx, void (*)(spng_ctx*)>;
using OpenFile = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

inline void checkSpng(int error, const std::string& what) {
    if (error != 0 && error != SPNG_EOI) {
        throw std::runtime_error(what + ": " + spng_strerror(error));
    }
}

inline std::vector<PngText> pngTexts(spng_ctx* context, bool afterPixels, std::uint32_t skip) {
    std::uint32_t count = 0;
    if (spng_get_text(context, nullptr, &count) != 0 || count <= skip) {
        return {};
    }
    std::vector<spng_text> chunks(count);
    checkSpng(spng_get_text(context, chunks.data(), &count), "spng_get_text");
    std::vector<PngText> texts;
    for (std::uint32_t i = skip; i < count; ++i) {
        texts.push_back({chunks[i].keyword, std::string(chunks[i].text, chunks[i].length), afterPixels});
    }
    return texts;
}

inline DecodedPng decodePng(const std::filesystem::path& path) {
    OpenFile file(std::fopen(path.c_str(), "rb"), std::fclose);
    SpngContext context(spng_ctx_new(0), spng_ctx_free);
    checkSpng(file ? spng_set_png_file(context.get(), file.get()) : SPNG_EINVAL, "open " + path.string());
    spng_ihdr header{};
    checkSpng(spng_get_ihdr(context.get(), &header), "spng_get_ihdr");
    DecodedPng png{header.width, header.height, {}, pngTexts(context.get(), false, 0)};
    const auto before = std::uint32_t(png.texts.size());
    png.rgb.resize(std::size_t(png.width) * png.height * 3);
    checkSpng(spng_decode_image(context.get(), png.rgb.data(), png.rgb.size(), SPNG_FMT_RGB8, 0), "decode");
    checkSpng(spng_decode_chunks(context.get()), "spng_decode_chunks");
    for (PngText& text : pngTexts(context.get(), true, before)) {
        png.texts.push_back(std::move(text));
    }
    return png;
}

// Writes `png` as 8-bit RGB; a text after the pixels is written as an "unknown" tEXt chunk,
// libspng's only way to put a chunk there.
inline void encodePng(const std::filesystem::path& path, const DecodedPng& png, bool interlaced = false) {
    OpenFile file(std::fopen(path.c_str(), "wb"), std::fclose);
    SpngContext context(spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free);
    checkSpng(file ? spng_set_png_file(context.get(), file.get()) : SPNG_EINVAL, "create " + path.string());
    spng_ihdr header{};
    header.width = png.width;
    header.height = png.height;
    header.bit_depth = 8;
    header.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
    header.interlace_method = interlaced ? SPNG_INTERLACE_ADAM7 : SPNG_INTERLACE_NONE;
    checkSpng(spng_set_ihdr(context.get(), &header), "spng_set_ihdr");
    std::vector<spng_text> before;
    std::vector<std::string> afterData;
    for (const PngText& text : png.texts) {
        if (text.afterPixels) {
            afterData.push_back(text.keyword + std::string(1, '\0') + text.text);
            continue;
        }
        spng_text chunk{};
        std::snprintf(chunk.keyword, sizeof chunk.keyword, "%s", text.keyword.c_str());
        chunk.type = SPNG_TEXT;
        chunk.length = text.text.size();
        chunk.text = const_cast<char*>(text.text.data());
        before.push_back(chunk);
    }
    if (!before.empty()) {
        checkSpng(spng_set_text(context.get(), before.data(), std::uint32_t(before.size())), "spng_set_text");
    }
    std::vector<spng_unknown_chunk> after(afterData.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        std::memcpy(after[i].type, "tEXt", 4);
        after[i].length = afterData[i].size();
        after[i].data = afterData[i].data();
        after[i].location = SPNG_AFTER_IDAT;
    }
    if (!after.empty()) {
        checkSpng(spng_set_unknown_chunks(context.get(), after.data(), std::uint32_t(after.size())), "unknown");
    }
    checkSpng(spng_encode_image(context.get(), png.rgb.data(), png.rgb.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE),
              "encode " + path.string());
}

}  // namespace hexray::test
