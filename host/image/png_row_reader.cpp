#include "image/png_row_reader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>
#include <vector>

#include <spng.h>

#include "image/image_io.h"

namespace hexray {

struct PngRowReader::Decoder {
    std::string name;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, std::fclose};
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> context{nullptr, spng_ctx_free};
    std::vector<std::pair<std::string, std::string>> texts;
    std::uint32_t rowsLeft = 0;

    void check(int spngError) const {
        if (spngError == SPNG_EMEM) {
            throw std::bad_alloc();
        }
        if (spngError != 0 && spngError != SPNG_EOI) {
            throw ImageIoError(name + ": cannot read PNG: " + spng_strerror(spngError));
        }
    }
};

PngRowReader::PngRowReader(const std::filesystem::path& path) : decoder_(std::make_unique<Decoder>()) {
    Decoder& d = *decoder_;
    d.name = path.string();
    d.file.reset(std::fopen(path.c_str(), "rb"));
    if (!d.file) {
        throw ImageIoError(d.name + ": cannot read PNG: " + std::strerror(errno));
    }
    d.context.reset(spng_ctx_new(0));
    if (!d.context) {
        throw std::bad_alloc();
    }
    d.check(spng_set_png_file(d.context.get(), d.file.get()));
    spng_ihdr header{};
    d.check(spng_get_ihdr(d.context.get(), &header));
    width_ = header.width;
    height_ = header.height;
    std::uint32_t count = 0;
    if (spng_get_text(d.context.get(), nullptr, &count) == 0 && count > 0) {
        std::vector<spng_text> chunks(count);
        d.check(spng_get_text(d.context.get(), chunks.data(), &count));
        for (const spng_text& chunk : chunks) {
            d.texts.emplace_back(chunk.keyword, std::string(chunk.text, chunk.length));
        }
    }
    d.check(spng_decode_image(d.context.get(), nullptr, 0, SPNG_FMT_RGB8, SPNG_DECODE_PROGRESSIVE));
    d.rowsLeft = height_;
}

PngRowReader::~PngRowReader() = default;

std::optional<std::string> PngRowReader::text(const std::string& key) const {
    for (const auto& [keyword, text] : decoder_->texts) {
        if (keyword == key) {
            return text;
        }
    }
    return std::nullopt;
}

void PngRowReader::readRows(std::span<std::uint8_t> rgbRows) {
    Decoder& d = *decoder_;
    const std::size_t rowBytes = std::size_t(width_) * 3;
    if (rgbRows.size() / rowBytes > d.rowsLeft) {
        throw ImageIoError(d.name + ": cannot read PNG: fewer rows than asked for");
    }
    for (std::size_t offset = 0; offset + rowBytes <= rgbRows.size(); offset += rowBytes) {
        d.check(spng_decode_row(d.context.get(), rgbRows.data() + offset, rowBytes));
        --d.rowsLeft;
    }
}

}  // namespace hexray
