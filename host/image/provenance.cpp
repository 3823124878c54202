#include "image/provenance.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <optional>

#include "image/exr_row_reader.h"
#include "image/png_row_reader.h"
#include "io/read_only_file.h"
#include "util/printable.h"

namespace hexray::inline image {
namespace {

// Longer than any version, device name or scene identity: a value past it was not written by hexray.
constexpr std::size_t kMaxValueBytes = 1024;

const std::string kVersion = "version";
const std::string kGitRevision = "git-revision";
const std::string kImage = "image";
const std::string kScene = "scene";
const std::string kBackend = "backend";
const std::string kDevice = "device";
const std::string kPrecision = "precision";
const std::string kSpp = "spp";
const std::string kResolution = "resolution";

std::string key(const std::string& field) {
    return kProvenanceKeyPrefix + field;
}

// The text fields, by their key's suffix, in the order records are written.
std::array<std::pair<const std::string*, std::string Provenance::*>, 7> textFields() {
    return {{{&kVersion, &Provenance::version},
             {&kGitRevision, &Provenance::gitRevision},
             {&kImage, &Provenance::image},
             {&kScene, &Provenance::scene},
             {&kBackend, &Provenance::backend},
             {&kDevice, &Provenance::device},
             {&kPrecision, &Provenance::precision}}};
}

std::optional<std::uint32_t> parseCount(std::string_view text) {
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || value == 0 || text[0] == '0') {
        return std::nullopt;
    }
    return value;
}

// What a device name or version may hold: UTF-8 without control characters (util/printable.h).
bool isRecordText(const std::string& text) {
    return text.size() <= kMaxValueBytes && printable(text) == text;
}

class RecordReader {
public:
    RecordReader(const std::vector<ImageNote>& notes, const std::string& source) : notes_(notes), source_(source) {}

    // The value of `field`, checked; nullopt when not recorded.
    std::optional<std::string> text(const std::string& field) const {
        std::optional<std::string> found;
        for (const ImageNote& note : notes_) {
            if (note.key != key(field)) {
                continue;
            }
            if (found) {
                fail(field, "recorded twice");
            }
            if (!isRecordText(note.text)) {
                fail(field, "not text a record holds (\"" + printable(note.text.substr(0, 80)) + "\")");
            }
            found = note.text;
        }
        return found;
    }

    std::uint32_t count(const std::string& field, std::string_view text) const {
        const std::optional<std::uint32_t> value = parseCount(text);
        if (!value) {
            fail(field, "not a positive decimal number (\"" + std::string(text) + "\")");
        }
        return *value;
    }

    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throw ImageIoError(printable(source_) + ": its " + key(field) + " is " + problem);
    }

private:
    const std::vector<ImageNote>& notes_;
    const std::string& source_;
};

// The first bytes of each format.
enum class FileKind { Png, Exr, Other };

FileKind kindOf(const ReadOnlyFile& file) {
    std::array<std::byte, 8> head{};
    const std::size_t read = file.readAt(0, head);
    const auto starts = [&](std::initializer_list<unsigned char> magic) {
        return read >= magic.size() && std::equal(magic.begin(), magic.end(), head.begin(),
                                                  [](unsigned char m, std::byte b) { return std::byte(m) == b; });
    };
    if (starts({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) {
        return FileKind::Png;
    }
    return starts({0x76, 0x2f, 0x31, 0x01}) ? FileKind::Exr : FileKind::Other;
}

}  // namespace

std::vector<ImageNote> Provenance::notes() const {
    std::vector<ImageNote> recorded;
    for (const auto& [field, member] : textFields()) {
        if (!(this->*member).empty()) {
            recorded.push_back({key(*field), this->*member});
        }
    }
    if (samplesPerPixel != 0) {
        recorded.push_back({key(kSpp), std::to_string(samplesPerPixel)});
    }
    if (width != 0 && height != 0) {
        recorded.push_back({key(kResolution), std::to_string(width) + "x" + std::to_string(height)});
    }
    return recorded;
}

std::string Provenance::describe() const {
    std::string text;
    for (const ImageNote& note : notes()) {
        text += note.key + " " + printable(note.text) + "\n";
    }
    return text;
}

const std::vector<std::string>& provenanceKeys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> all;
        for (const auto& field : textFields()) {
            all.push_back(key(*field.first));
        }
        all.push_back(key(kSpp));
        all.push_back(key(kResolution));
        return all;
    }();
    return keys;
}

Provenance provenanceFromNotes(const std::vector<ImageNote>& notes, const std::string& source) {
    const RecordReader reader(notes, source);
    Provenance provenance;
    for (const auto& [field, member] : textFields()) {
        provenance.*member = reader.text(*field).value_or("");
    }
    if (const std::optional<std::string> spp = reader.text(kSpp)) {
        provenance.samplesPerPixel = reader.count(kSpp, *spp);
    }
    if (const std::optional<std::string> resolution = reader.text(kResolution)) {
        const std::size_t x = resolution->find('x');
        if (x == std::string::npos) {
            reader.fail(kResolution, "not WIDTHxHEIGHT (\"" + *resolution + "\")");
        }
        provenance.width = reader.count(kResolution, std::string_view(*resolution).substr(0, x));
        provenance.height = reader.count(kResolution, std::string_view(*resolution).substr(x + 1));
    }
    return provenance;
}

Provenance readProvenance(const std::filesystem::path& path) {
    std::vector<ImageNote> notes;
    try {
        const ReadOnlyFile file(path.string());
        const FileKind kind = kindOf(file);
        if (kind == FileKind::Png) {
            const PngRowReader png(file);
            for (const std::string& name : provenanceKeys()) {
                if (const std::optional<std::string> text = png.text(name)) {
                    notes.push_back({name, *text});
                }
            }
        } else if (kind == FileKind::Exr) {
            const ExrRowReader exr(path);
            for (const std::string& name : provenanceKeys()) {
                if (const std::optional<std::string> text = exr.stringAttribute(name)) {
                    notes.push_back({name, *text});
                }
            }
        } else {
            throw ImageIoError(printable(path.string()) + ": neither a PNG nor an OpenEXR file");
        }
    } catch (const InputError& error) {
        throw ImageIoError(error.what());
    }
    return provenanceFromNotes(notes, path.string());
}

}  // namespace hexray::image
