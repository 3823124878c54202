#include "image/exr_rgb_row_reader.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <vector>

#include <OpenEXR/openexr.h>

#include "image/image_io.h"
#include "scene/scene.h"

namespace hexray::inline image {
namespace {

constexpr std::array<const char*, 3> kChannels = {"R", "G", "B"};

const char* compressionName(exr_compression_t compression) {
    static constexpr std::array<const char*, 10> kNames = {"none",  "RLE", "ZIPS", "ZIP",  "PIZ",
                                                           "PXR24", "B44", "B44A", "DWAA", "DWAB"};
    return std::size_t(compression) < kNames.size() ? kNames[std::size_t(compression)] : "an unknown method";
}

}  // namespace

struct ExrRgbRowReader::Decoder {
    const ReadOnlyFile& file;
    std::string failure;  // OpenEXRCore's last message, or why the file could not be read
    exr_context_t context = nullptr;
    exr_decode_pipeline_t pipeline{};  // EXR_DECODE_PIPELINE_INITIALIZER: all zero
    bool pipelineStarted = false;
    exr_attr_box2i_t window{};
    std::uint32_t width = 0;
    std::uint32_t nextRow = 0;
    std::uint32_t chunkFirst = 0;  // the rows decoded into `chunk`
    std::uint32_t chunkRows = 0;
    std::array<std::vector<float>, 3> chunk;  // R, G, B planes

    explicit Decoder(const ReadOnlyFile& readFrom) : file(readFrom) {}
    ~Decoder() {
        if (pipelineStarted) {
            exr_decoding_destroy(context, &pipeline);
        }
        if (context) {
            exr_finish(&context);
        }
    }

    static Decoder& of(exr_const_context_t context) {
        void* user = nullptr;
        exr_get_user_data(context, &user);
        return *static_cast<Decoder*>(user);
    }
    static void report(exr_const_context_t context, exr_result_t, const char* message) {
        if (context) {
            of(context).failure = message;
        }
    }
    static int64_t read(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                        exr_stream_error_func_ptr_t) {
        auto& d = *static_cast<Decoder*>(user);
        try {
            return int64_t(d.file.readAt(offset, {static_cast<std::byte*>(buffer), std::size_t(size)}));
        } catch (const InputError& error) {
            d.failure = error.what();
            return -1;
        }
    }
    static int64_t size(exr_const_context_t, void* user) {
        auto& d = *static_cast<Decoder*>(user);
        try {
            return int64_t(d.file.size());
        } catch (const InputError& error) {
            d.failure = error.what();
            return -1;
        }
    }

    [[noreturn]] void fail(const std::string& why) const { throw ImageIoError(file.name() + ": " + why); }
    void check(exr_result_t result) const {
        if (result == EXR_ERR_OUT_OF_MEMORY) {
            throw std::bad_alloc();
        }
        if (result != EXR_ERR_SUCCESS) {
            fail("cannot read OpenEXR: " + (failure.empty() ? exr_get_default_error_message(result) : failure));
        }
    }

    void open();
    void checkLayout() const;
    void decodeChunk(std::uint32_t row);
};

void ExrRgbRowReader::Decoder::open() {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = &Decoder::report;
    init.user_data = this;
    init.read_fn = &Decoder::read;
    init.size_fn = &Decoder::size;
    init.max_image_width = int(kMaxImageDimension);
    init.max_image_height = int(kMaxImageDimension);
    init.max_tile_width = 1;  // no tiles
    init.max_tile_height = 1;
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    check(exr_start_read(&context, file.name().c_str(), &init));
    checkLayout();
    check(exr_get_data_window(context, 0, &window));
    width = std::uint32_t(int64_t(window.max.x) - window.min.x + 1);
}

// Refuses by name what hexray does not write and merge does not read.
void ExrRgbRowReader::Decoder::checkLayout() const {
    int parts = 0;
    check(exr_get_count(context, &parts));
    if (parts != 1) {
        fail("an OpenEXR file of " + std::to_string(parts) + " parts, which merge does not read: hexray writes one");
    }
    exr_storage_t storage{};
    check(exr_get_storage(context, 0, &storage));
    if (storage != EXR_STORAGE_SCANLINE) {
        fail("a tiled or deep OpenEXR file, which merge does not read: hexray writes scanlines");
    }
    exr_compression_t compression{};
    check(exr_get_compression(context, 0, &compression));
    if (compression != EXR_COMPRESSION_NONE && compression != EXR_COMPRESSION_RLE &&
        compression != EXR_COMPRESSION_ZIPS && compression != EXR_COMPRESSION_ZIP) {
        fail(std::string("an OpenEXR file compressed with ") + compressionName(compression) +
             ", which merge does not read: save it with ZIP compression, as hexray wrote it");
    }
    const exr_attr_chlist_t* channels = nullptr;
    check(exr_get_channels(context, 0, &channels));
    if (channels->num_channels > kMaxExrChannels) {
        fail("an OpenEXR file of " + std::to_string(channels->num_channels) + " channels, more than merge reads (" +
             std::to_string(kMaxExrChannels) + ")");
    }
    for (const char* name : kChannels) {
        const auto* end = channels->entries + channels->num_channels;
        const auto* found = std::find_if(channels->entries, end, [&](const exr_attr_chlist_entry_t& entry) {
            return std::strcmp(entry.name.str, name) == 0;
        });
        if (found == end) {
            fail(std::string("not an image hexray wrote (no channel ") + name + ")");
        }
        if (found->pixel_type != EXR_PIXEL_FLOAT) {
            fail(std::string("channel ") + name + " is not of 32-bit floats, as hexray writes it");
        }
    }
    for (int c = 0; c < channels->num_channels; ++c) {
        if (channels->entries[c].x_sampling != 1 || channels->entries[c].y_sampling != 1) {
            fail(std::string("channel ") + channels->entries[c].name.str +
                 " is subsampled, which merge does not read: hexray writes every pixel");
        }
    }
}

// Decodes the chunk (a band of scanlines) holding `row` into `chunk`.
void ExrRgbRowReader::Decoder::decodeChunk(std::uint32_t row) {
    exr_chunk_info_t info{};
    check(exr_read_scanline_chunk_info(context, 0, int(int64_t(window.min.y) + row), &info));
    const int64_t first = int64_t(info.start_y) - window.min.y;
    if (first < 0 || first > row || info.height <= 0 || first + info.height <= row || info.width != int(width)) {
        fail("cannot read OpenEXR: a chunk of scanlines is not where its header puts it");
    }
    for (std::vector<float>& plane : chunk) {
        plane.resize(std::size_t(info.height) * width);
    }
    check(pipelineStarted ? exr_decoding_update(context, 0, &info, &pipeline)
                          : exr_decoding_initialize(context, 0, &info, &pipeline));
    pipelineStarted = true;
    for (int c = 0; c < pipeline.channel_count; ++c) {
        exr_coding_channel_info_t& channel = pipeline.channels[c];
        channel.decode_to_ptr = nullptr;  // a channel merge does not use is skipped
        for (std::size_t k = 0; k < kChannels.size(); ++k) {
            if (std::strcmp(channel.channel_name, kChannels[k]) == 0) {
                channel.decode_to_ptr = reinterpret_cast<uint8_t*>(chunk[k].data());
                channel.user_pixel_stride = int32_t(sizeof(float));
                channel.user_line_stride = int32_t(sizeof(float) * width);
                channel.user_bytes_per_element = int16_t(sizeof(float));
                channel.user_data_type = EXR_PIXEL_FLOAT;
            }
        }
    }
    check(exr_decoding_choose_default_routines(context, 0, &pipeline));
    check(exr_decoding_run(context, 0, &pipeline));
    chunkFirst = std::uint32_t(first);
    chunkRows = std::uint32_t(info.height);
}

ExrRgbRowReader::ExrRgbRowReader(const ReadOnlyFile& file) : decoder_(std::make_unique<Decoder>(file)) {
    Decoder& d = *decoder_;
    d.open();
    width_ = d.width;
    height_ = std::uint32_t(int64_t(d.window.max.y) - d.window.min.y + 1);
}

ExrRgbRowReader::~ExrRgbRowReader() = default;

std::optional<std::string> ExrRgbRowReader::stringAttribute(const std::string& name) const {
    int32_t length = 0;
    const char* text = nullptr;
    const exr_result_t result = exr_attr_get_string(decoder_->context, 0, name.c_str(), &length, &text);
    if (result == EXR_ERR_NO_ATTR_BY_NAME) {
        return std::nullopt;
    }
    decoder_->check(result);
    return std::string(text, std::size_t(length));
}

void ExrRgbRowReader::readRows(std::uint32_t rows, std::span<float> red, std::span<float> green,
                               std::span<float> blue) {
    Decoder& d = *decoder_;
    const std::size_t values = std::size_t(rows) * width_;
    if (rows > height_ - d.nextRow || red.size() != values || green.size() != values || blue.size() != values) {
        throw ImageIoError(d.file.name() + ": cannot read OpenEXR: fewer rows than asked for");
    }
    const std::array<std::span<float>, 3> out = {red, green, blue};
    for (std::uint32_t done = 0; done < rows;) {
        if (d.nextRow < d.chunkFirst || d.nextRow >= d.chunkFirst + d.chunkRows) {
            d.decodeChunk(d.nextRow);
        }
        const std::uint32_t take = std::min(rows - done, d.chunkFirst + d.chunkRows - d.nextRow);
        const std::size_t from = std::size_t(d.nextRow - d.chunkFirst) * width_;
        for (std::size_t k = 0; k < out.size(); ++k) {
            std::copy_n(d.chunk[k].begin() + std::ptrdiff_t(from), std::size_t(take) * width_,
                        out[k].begin() + std::ptrdiff_t(std::size_t(done) * width_));
        }
        done += take;
        d.nextRow += take;
    }
}

}  // namespace hexray::image
