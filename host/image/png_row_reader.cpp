#include "image/png_row_reader.h"

#include <cstring>
#include <new>
#include <utility>
#include <vector>

#include <spng.h>

#include "image/image_io.h"

namespace hexray::inline image {
namespace {

// Ancillary chunks are kept in memory: a text chunk of up to 1 MiB, 4 MiB of them in all, far
// above what hexray writes (a stamp of a few hundred bytes) or a PNG optimiser keeps.
constexpr std::size_t kMaxChunkBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxChunkCacheBytes = std::size_t{4} << 20;

}  // namespace

struct PngRowReader::Decoder {
    struct TextChunk {
        std::string keyword;
        std::string text;
    };

    const ReadOnlyFile& file;
    std::uint64_t offset = 0;  // the next byte libspng reads
    std::string readFailure;   // why the file could not be read, if it could not
    std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> context{nullptr, spng_ctx_free};
    std::vector<TextChunk> textsBefore;
    std::vector<TextChunk> textsAfter;
    std::uint32_t rowsLeft = 0;
    bool decoding = false;
    bool finished = false;

    explicit Decoder(const ReadOnlyFile& readFrom) : file(readFrom) {}

    static int read(spng_ctx*, void* user, void* destination, std::size_t length) {
        auto& d = *static_cast<Decoder*>(user);
        try {
            const std::size_t read = d.file.readAt(d.offset, {static_cast<std::byte*>(destination), length});
            d.offset += read;
            return read == length ? 0 : SPNG_IO_EOF;
        } catch (const InputError& error) {
            d.readFailure = error.what();
            return SPNG_IO_ERROR;
        }
    }

    void check(int spngError) const {
        if (spngError == SPNG_EMEM) {
            throw std::bad_alloc();
        }
        if (!readFailure.empty()) {
            throw ImageIoError(readFailure);
        }
        if (spngError != 0 && spngError != SPNG_EOI) {
            throw ImageIoError(file.name() + ": cannot read PNG: " + spng_strerror(spngError));
        }
    }

    // The text chunks read so far from the `skip`th on.
    std::vector<TextChunk> texts(std::uint32_t skip) const {
        std::uint32_t count = 0;
        const int error = spng_get_text(context.get(), nullptr, &count);
        if (error == SPNG_ECHUNKAVAIL) {
            return {};  // none at all
        }
        check(error);
        if (count <= skip) {
            return {};
        }
        std::vector<spng_text> chunks(count);
        check(spng_get_text(context.get(), chunks.data(), &count));
        std::vector<TextChunk> found;
        for (std::uint32_t i = skip; i < count; ++i) {
            found.push_back({chunks[i].keyword, std::string(chunks[i].text, chunks[i].length)});
        }
        return found;
    }

    std::optional<std::string> find(const std::vector<TextChunk>& chunks, const std::string& key,
                                    const char* where) const {
        std::optional<std::string> text;
        for (const TextChunk& chunk : chunks) {
            if (chunk.keyword != key)
                continue;
            if (text) {
                throw ImageIoError(file.name() + ": two " + key + " text chunks " + where + " the pixels");
            }
            text = chunk.text;
        }
        return text;
    }
};

PngRowReader::PngRowReader(const ReadOnlyFile& file) : decoder_(std::make_unique<Decoder>(file)) {
    Decoder& d = *decoder_;
    d.context.reset(spng_ctx_new(0));
    if (!d.context) {
        throw std::bad_alloc();
    }
    d.check(spng_set_chunk_limits(d.context.get(), kMaxChunkBytes, kMaxChunkCacheBytes));
    d.check(spng_set_png_stream(d.context.get(), &Decoder::read, &d));
    spng_ihdr header{};
    d.check(spng_get_ihdr(d.context.get(), &header));
    if (header.interlace_method != SPNG_INTERLACE_NONE) {
        throw ImageIoError(file.name() +
                           ": an interlaced PNG, which merge does not read (it reads a band of rows at "
                           "a time, and interlaced rows come in seven passes): save it without "
                           "interlacing, as hexray wrote it");
    }
    width_ = header.width;
    height_ = header.height;
    d.textsBefore = d.texts(0);
}

PngRowReader::~PngRowReader() = default;

std::optional<std::string> PngRowReader::text(const std::string& key) const {
    return decoder_->find(decoder_->textsBefore, key, "before");
}

void PngRowReader::readRows(std::span<std::uint8_t> rgbRows) {
    Decoder& d = *decoder_;
    if (!d.decoding) {
        // Only now are the row buffers allocated, from the width the caller has seen.
        d.check(spng_decode_image(d.context.get(), nullptr, 0, SPNG_FMT_RGB8, SPNG_DECODE_PROGRESSIVE));
        d.decoding = true;
        d.rowsLeft = height_;
    }
    const std::size_t rowBytes = std::size_t(width_) * 3;
    if (rgbRows.size() % rowBytes != 0 || rgbRows.size() / rowBytes > d.rowsLeft) {
        throw ImageIoError(d.file.name() + ": cannot read PNG: fewer rows than asked for");
    }
    for (std::size_t offset = 0; offset < rgbRows.size(); offset += rowBytes) {
        d.check(spng_decode_row(d.context.get(), rgbRows.data() + offset, rowBytes));
        --d.rowsLeft;
    }
}

std::optional<std::string> PngRowReader::textAfterPixels(const std::string& key) {
    Decoder& d = *decoder_;
    if (!d.decoding || d.rowsLeft != 0) {
        throw ImageIoError(d.file.name() + ": cannot read PNG: the chunks after the pixels come after every row");
    }
    if (!d.finished) {
        d.check(spng_decode_chunks(d.context.get()));  // to IEND
        d.textsAfter = d.texts(std::uint32_t(d.textsBefore.size()));
        d.finished = true;
    }
    return d.find(d.textsAfter, key, "after");
}

}  // namespace hexray::image
