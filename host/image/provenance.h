#pragma once
// What made an image file: the record every PNG (tEXt chunks before the pixels) and OpenEXR file
// (string attributes in the header) hexray writes carries, one key-value pair a field, each key
// starting with kProvenanceKeyPrefix:
//   hexray:version 0.1.0              hexray:git-revision 9317900a2b4c
//   hexray:image render               hexray:scene 5f0c3e2a9b1d4c77/1187
//   hexray:backend gpu                hexray:device llvmpipe (LLVM 15.0.6, 256 bits)
//   hexray:precision f32              hexray:spp 4              hexray:resolution 640x480
// Whoever writes the image fills it in; the writers only record what they are given. A field
// left empty (or 0) is not recorded: a heat map of two renders has no single backend.
//
// To read it back: readProvenance(path), empty() when the file has no record. Its notes() are the
// fields in a fixed order, ready to print (`key value` a line, the way describe() does); two
// records are compared with ==.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"

namespace hexray::inline image {

inline constexpr const char* kProvenanceKeyPrefix = "hexray:";

struct Provenance {
    std::string version;      // hexray's (util/build_version.h): "0.1.0"
    std::string gitRevision;  // the commit it was built from: "9317900a2b4c"
    std::string image;        // what the file shows: "render", "diff heat map", "mismatch mask", "aov depth", ...
    std::string scene;        // the scene file's identity, as a strip's stamp has it (strip/strip_stamp.h)
    std::string backend;      // "gpu", "cpu", or "gpu vs cpu" for a comparison's images
    std::string device;       // the Vulkan device's name, or "cpu reference"
    std::string precision;    // the precision actually rendered in ("f32", "f64", ...), not the one asked for
    std::uint32_t samplesPerPixel = 0;
    std::uint32_t width = 0;  // the whole image's, also for a strip of it
    std::uint32_t height = 0;

    bool empty() const { return notes().empty(); }
    bool operator==(const Provenance&) const = default;

    // The recorded fields as notes for an image writer (image_io.h), keys with the prefix.
    std::vector<ImageNote> notes() const;
    // `key value` a line, for a person.
    std::string describe() const;
};

// Every key a record may have, in the order notes() gives them.
const std::vector<std::string>& provenanceKeys();

// The record in `notes` (other keys ignored). Throws ImageIoError naming `source` and the key
// when a value is not text a record holds (a control character, over 1024 bytes) or not of its
// field's form (spp a decimal number, resolution WxH).
Provenance provenanceFromNotes(const std::vector<ImageNote>& notes, const std::string& source);

// The record of the PNG or OpenEXR file at `path` (told apart by their first bytes, not the
// name); empty when it has none. Reads only the header. Throws ImageIoError naming the file when
// it cannot be read, is neither format, or holds a malformed record.
Provenance readProvenance(const std::filesystem::path& path);

}  // namespace hexray::image
