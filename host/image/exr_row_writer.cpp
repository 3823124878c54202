#include "image/exr_row_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "io/anonymous_file.h"
#include "io/output_error.h"
#include "io/output_file.h"

namespace hexray::inline image {

// Outside the anonymous namespace: Encoder, which has external linkage, holds one.
// OpenEXR's output stream over a stdio stream: the OutputFile's own, or a scratch copy of it.
// Failures throw the OutputFile's OutputError, `what` saying which was written. It keeps a copy
// of what is written while capturing (the header), so that a note's text can be found there again.
class ExrStdioStream : public Imf::OStream {
public:
    ExrStdioStream(std::FILE* stream, const OutputFile& file, std::string what)
        : Imf::OStream(file.name().c_str()), stream_(stream), file_(file), what_(std::move(what)) {}

    void write(const char bytes[], int count) override {
        if (capturing && tellp() == captured.size()) {
            captured.append(bytes, std::size_t(count));
        }
        if (std::fwrite(bytes, 1, std::size_t(count), stream_) != std::size_t(count)) {
            file_.fail(what_, std::strerror(errno));
        }
    }
    uint64_t tellp() override { return std::uint64_t(::ftello(stream_)); }
    void seekp(uint64_t position) override {
        if (::fseeko(stream_, off_t(position), SEEK_SET) != 0) {
            file_.fail(what_, std::strerror(errno));
        }
    }

    bool capturing = false;
    std::string captured;  // the file's first bytes

private:
    std::FILE* stream_;
    const OutputFile& file_;
    std::string what_;
};

namespace {

// Where OpenEXR writes: the output itself where it can seek back (a regular file hexray
// creates), else an unnamed scratch file, copied to the output once complete.
FilePointer scratchCopyFor(const OutputFile& file) {
    if (file.seekable()) {
        return nullptr;
    }
    FilePointer scratch = openAnonymousFile();
    if (!scratch) {
        const std::string why = std::strerror(errno);
        file.fail("cannot create output file",
                  "no scratch file in " + scratchDirectory() + " (OpenEXR is written whole, then streamed): " + why);
    }
    return scratch;
}

// The scratch copy's bytes, from the start, to the output.
void copyToOutput(std::FILE* scratch, const OutputFile& file) {
    const std::string scratchWhat = "cannot write its scratch copy in " + scratchDirectory();
    if (std::fflush(scratch) != 0 || std::ferror(scratch) || std::fseek(scratch, 0, SEEK_SET) != 0) {
        file.fail(scratchWhat, std::strerror(errno));
    }
    std::vector<char> buffer(std::size_t{1} << 16);
    while (const std::size_t count = std::fread(buffer.data(), 1, buffer.size(), scratch)) {
        if (std::fwrite(buffer.data(), 1, count, file.stream()) != count) {
            file.fail("cannot write", std::strerror(errno));
        }
    }
    if (std::ferror(scratch)) {
        file.fail(scratchWhat, std::strerror(errno));
    }
}

// Where OpenEXR wrote `note`'s text: a string attribute is its name, NUL, "string", NUL, its
// length (4 bytes, little-endian), then its text. npos unless exactly once in `header`.
std::size_t textOffset(const std::string& header, const ImageNote& note) {
    std::string attribute = note.key + std::string(1, '\0') + "string" + std::string(1, '\0');
    for (int shift = 0; shift < 32; shift += 8) {
        attribute += char((note.text.size() >> shift) & 0xff);
    }
    const std::size_t at = header.find(attribute + note.text);
    if (at == std::string::npos || header.find(attribute + note.text, at + 1) != std::string::npos) {
        return std::string::npos;
    }
    return at + attribute.size();
}

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
    // Declared in this order so the encoder is released before the stream and the files.
    OutputFile file;
    FilePointer scratch;  // null where OpenEXR writes the file itself
    ExrStdioStream stream;
    std::unique_ptr<Imf::OutputFile> exr;
    std::vector<std::string> channelNames;
    std::vector<ImageNote> notes;
    std::uint32_t width;
    std::uint32_t height;
    std::uint32_t rowsWritten = 0;

    Encoder(const std::filesystem::path& path, std::uint32_t w, std::uint32_t h, const std::vector<std::string>& names,
            const std::vector<ImageNote>& imageNotes)
        : file(path.string()),
          scratch(scratchCopyFor(file)),
          stream(scratch ? scratch.get() : file.stream(), file,
                 scratch ? "cannot write its scratch copy in " + scratchDirectory() : "cannot write"),
          channelNames(names),
          notes(imageNotes),
          width(w),
          height(h) {}

    // Overwrites the text of the note `replacement.key` in the header written.
    void replaceText(const ImageNote& replacement) {
        const auto note =
            std::find_if(notes.begin(), notes.end(), [&](const ImageNote& n) { return n.key == replacement.key; });
        if (note == notes.end() || note->text.size() != replacement.text.size()) {
            throw std::invalid_argument("ExrRowWriter::finish: no note " + replacement.key + " of that length");
        }
        const std::size_t offset = textOffset(stream.captured, *note);
        if (offset == std::string::npos) {
            file.fail("cannot write", "the note " + note->key + " is not where OpenEXR was to write it");
        }
        stream.seekp(offset);
        stream.write(replacement.text.data(), int(replacement.text.size()));
    }

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
    : encoder_(std::make_unique<Encoder>(path, width, height, channelNames, notes)) {
    Encoder& e = *encoder_;
    e.stream.capturing = true;  // OpenEXR writes the header as the file is created
    e.guard(
        [&] { e.exr = std::make_unique<Imf::OutputFile>(e.stream, headerFor(width, height, channelNames, notes)); });
    e.stream.capturing = false;
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
            throw std::invalid_argument("ExrRowWriter::writeRows: channel " + e.channelNames[c] +
                                        " has the wrong size");
        }
        frame.insert(e.channelNames[c], Imf::Slice::Make(Imf::FLOAT, channels[c].data(),
                                                         Imath::V2i(0, int(e.rowsWritten)), e.width, rows));
    }
    e.guard([&] {
        e.exr->setFrameBuffer(frame);
        e.exr->writePixels(int(rows));
    });
    e.rowsWritten += rows;
}

void ExrRowWriter::finish(const std::vector<ImageNote>& replacements) {
    Encoder& e = *encoder_;
    if (e.rowsWritten != e.height) {
        e.file.fail("cannot write", std::to_string(e.height - e.rowsWritten) + " rows were never rendered");
    }
    e.exr.reset();  // writes the offset table; a failed write there leaves the stream's error flag set
    for (const ImageNote& replacement : replacements) {
        e.replaceText(replacement);
    }
    if (e.scratch) {
        copyToOutput(e.scratch.get(), e.file);
    }
    e.file.commit();
}

}  // namespace hexray::image
