#include "image/exr_row_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "io/output_error.h"
#include "io/output_file.h"

namespace hexray {
namespace {

// OpenEXR's output stream over the OutputFile's stdio stream.
class StdioStream : public Imf::OStream {
public:
    explicit StdioStream(const OutputFile& file) : Imf::OStream(file.name().c_str()), file_(file) {}

    void write(const char bytes[], int count) override {
        if (std::fwrite(bytes, 1, std::size_t(count), file_.stream()) != std::size_t(count)) {
            file_.fail("cannot write", std::strerror(errno));
        }
    }
    uint64_t tellp() override { return std::uint64_t(::ftello(file_.stream())); }
    void seekp(uint64_t position) override {
        if (::fseeko(file_.stream(), off_t(position), SEEK_SET) != 0) {
            file_.fail("cannot write", std::strerror(errno));
        }
    }

private:
    const OutputFile& file_;
};

Imf::Header headerFor(std::uint32_t width, std::uint32_t height, const std::vector<std::string>& channelNames,
                      const std::vector<ImageNote>& notes) {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const std::string& name : channelNames) {
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    for (const ImageNote& note : notes) {
        header.insert(note.key, Imf::StringAttribute(note.text));
    }
    return header;
}

}  // namespace

struct ExrRowWriter::Encoder {
    // Declared in this order so the encoder is released before the stream and the file.
    OutputFile file;
    StdioStream stream;
    std::unique_ptr<Imf::OutputFile> exr;
    std::vector<std::string> channelNames;
    std::uint32_t width;
    std::uint32_t height;
    std::uint32_t rowsWritten = 0;

    Encoder(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, const std::vector<std::string>& names)
        : file(path.string()), stream(file), channelNames(names), width(w), height(h) {}

    // Runs an OpenEXR call, turning its exceptions (Iex) into OutputError naming the file.
    template <class Call>
    void guard(Call&& call) {
        try {
            call();
        } catch (const OutputError&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception& error) {
            file.fail("cannot write", error.what());
        }
    }
};

ExrRowWriter::ExrRowWriter(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                           const std::vector<std::string>& channelNames, const std::vector<ImageNote>& notes)
    : encoder_(std::make_unique<Encoder>(path, width, height, channelNames)) {
    Encoder& e = *encoder_;
    e.guard([&] {
        e.exr = std::make_unique<Imf::OutputFile>(e.stream, headerFor(width, height, channelNames, notes));
    });
}

ExrRowWriter::~ExrRowWriter() = default;

void ExrRowWriter::writeRows(std::uint32_t rows, const std::vector<std::span<const float>>& channels) {
    Encoder& e = *encoder_;
    if (rows > e.height - e.rowsWritten || channels.size() != e.channelNames.size()) {
        throw std::invalid_argument("ExrRowWriter::writeRows: more rows than the image has, or a channel missing");
    }
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        if (channels[c].size() != std::size_t(rows) * e.width) {
            throw std::invalid_argument("ExrRowWriter::writeRows: channel " + e.channelNames[c] + " has the wrong size");
        }
        frame.insert(e.channelNames[c], Imf::Slice::Make(Imf::FLOAT, channels[c].data(), Imath::V2i(0, int(e.rowsWritten)),
                                                         e.width, rows));
    }
    e.guard([&] {
        e.exr->setFrameBuffer(frame);
        e.exr->writePixels(int(rows));
    });
    e.rowsWritten += rows;
}

void ExrRowWriter::finish() {
    Encoder& e = *encoder_;
    if (e.rowsWritten != e.height) {
        e.file.fail("cannot write", std::to_string(e.height - e.rowsWritten) + " rows were never rendered");
    }
    e.exr.reset();  // writes the offset table; a failed write there leaves the stream's error flag set
    e.file.commit();
}

}  // namespace hexray
