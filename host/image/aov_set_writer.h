#pragma once
// Writes every file of an AOV set (see aov.h) into a directory, band by band: each EXR and its
// preview are written as the rows arrive, except the depth preview, whose colour scale spans the
// whole image's depths: it is drawn at finish() from the finished depth file.

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "image/aov.h"
#include "image/exr_row_writer.h"
#include "image/image_io.h"
#include "image/provenance.h"

namespace hexray::inline image {

class AovSetWriter {
public:
    // Opens every file; throws OutputError when one cannot be created. Each records `provenance`,
    // its image named for the AOV ("aov depth", "aov depth preview").
    AovSetWriter(const std::filesystem::path& directory, const AovLayout& layout, const Provenance& provenance);
    ~AovSetWriter();
    AovSetWriter(const AovSetWriter&) = delete;
    AovSetWriter& operator=(const AovSetWriter&) = delete;

    void writeRows(const AovBand& band);

    // Finishes every file; returns their names, in the order written.
    std::vector<std::string> finish();

private:
    // One AOV: its EXR and its preview (the depth's preview is opened by finish()).
    struct File {
        std::string name;
        std::unique_ptr<ExrRowWriter> exr;
        std::unique_ptr<PngRowWriter> preview;
    };

    void open(const std::string& name, const std::vector<std::string>& channels, bool withPreview = true);
    void writeDepth(const AovBand& band);
    void writeNormals(const AovBand& band);
    void writeObjectIds(const AovBand& band);
    void writeLights(const AovBand& band);
    void writeMargins(const AovBand& band);
    void drawDepthPreview();
    std::vector<ImageNote> notesFor(const std::string& image) const;

    std::filesystem::path directory_;
    AovLayout layout_;
    Provenance provenance_;
    std::vector<File> files_;  // depth, normal, object-id, light-0, light-1, ..., margin
    float nearest_ = std::numeric_limits<float>::infinity();
    float farthest_ = 0.0f;
};

}  // namespace hexray::image
