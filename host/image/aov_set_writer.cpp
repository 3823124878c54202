#include "image/aov_set_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "image/exr_row_reader.h"

namespace hexray::inline image {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr std::size_t kDepth = 0;
constexpr std::size_t kNormal = 1;
constexpr std::size_t kObjectId = 2;
constexpr std::size_t kFirstLight = 3;

// Rows read back at a time for the depth preview.
constexpr std::size_t kPreviewBandBytes = std::size_t{4} << 20;

// A perceptually ordered ramp from dark blue (0) through magenta and orange to yellow (1).
Rgb ramp(double t) {
    static constexpr std::array<std::array<double, 3>, 5> kStops = {
        {{0.05, 0.03, 0.35}, {0.45, 0.05, 0.55}, {0.85, 0.25, 0.35}, {0.98, 0.60, 0.10}, {1.0, 0.98, 0.55}}};
    t = std::clamp(t, 0.0, 1.0) * double(kStops.size() - 1);
    const std::size_t i = std::min<std::size_t>(std::size_t(t), kStops.size() - 2);
    const double f = t - double(i);
    Rgb out;
    for (int c = 0; c < 3; ++c) {
        out[c] = std::uint8_t(std::lround(255.0 * (kStops[i][c] * (1.0 - f) + kStops[i + 1][c] * f)));
    }
    return out;
}

// Distinct colours for neighbouring node indices: hues a golden angle apart.
Rgb idColour(std::uint32_t id) {
    const double hue = std::fmod(double(id) * 0.6180339887498949, 1.0) * 6.0;
    const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
    std::array<double, 3> rgb{};
    switch (int(hue)) {
        case 0:
            rgb = {1, x, 0};
            break;
        case 1:
            rgb = {x, 1, 0};
            break;
        case 2:
            rgb = {0, 1, x};
            break;
        case 3:
            rgb = {0, x, 1};
            break;
        case 4:
            rgb = {x, 0, 1};
            break;
        default:
            rgb = {1, 0, x};
            break;
    }
    return {std::uint8_t(55 + 200 * rgb[0]), std::uint8_t(55 + 200 * rgb[1]), std::uint8_t(55 + 200 * rgb[2])};
}

// `count` pixels' preview colours, as PNG rows.
template <class PixelColour>
std::vector<std::uint8_t> previewRows(std::size_t count, PixelColour&& colour) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(3 * count);
    for (std::size_t i = 0; i < count; ++i) {
        const Rgb rgb = colour(i);
        bytes.insert(bytes.end(), rgb.begin(), rgb.end());
    }
    return bytes;
}

bool isBackground(const PixelClass& pixel) {
    return pixel.node == PixelClass::kBackground;
}

}  // namespace

AovSetWriter::AovSetWriter(const std::filesystem::path& directory, const AovLayout& layout,
                           const Provenance& provenance)
    : directory_(directory), layout_(layout), provenance_(provenance) {
    open("depth", {"Y"}, false);
    open("normal", {"R", "G", "B"});
    open("object-id", {"Y"});
    for (std::size_t light = 0; light < std::min<std::size_t>(layout.lightCount, PixelClass::kClassifiedLights);
         ++light) {
        open("light-" + std::to_string(light), {"Y"});
    }
    if (layout.withMargins) {
        open("margin", {"Y"});
    }
}

AovSetWriter::~AovSetWriter() = default;

std::vector<ImageNote> AovSetWriter::notesFor(const std::string& image) const {
    Provenance provenance = provenance_;
    provenance.image = image;
    return provenance.notes();
}

void AovSetWriter::open(const std::string& name, const std::vector<std::string>& channels, bool withPreview) {
    File file{name,
              std::make_unique<ExrRowWriter>(directory_ / (name + ".exr"), layout_.width, layout_.height, channels,
                                             notesFor("aov " + name)),
              nullptr};
    if (withPreview) {
        file.preview = std::make_unique<PngRowWriter>(directory_ / (name + ".png"), layout_.width, layout_.height,
                                                      notesFor("aov " + name + " preview"));
    }
    files_.push_back(std::move(file));
}

void AovSetWriter::writeRows(const AovBand& band) {
    const std::size_t count = std::size_t(band.rows) * layout_.width;
    if (band.depth.size() != count || band.normals.size() != count || band.classes.size() != count ||
        band.margins.size() != (layout_.withMargins ? count : 0)) {
        throw std::invalid_argument("AovSetWriter::writeRows: an AOV band of the wrong size");
    }
    writeDepth(band);
    writeNormals(band);
    writeObjectIds(band);
    writeLights(band);
    if (layout_.withMargins) {
        writeMargins(band);
    }
}

void AovSetWriter::writeDepth(const AovBand& band) {
    for (const float d : band.depth) {
        if (std::isfinite(d)) {
            nearest_ = std::min(nearest_, d);
            farthest_ = std::max(farthest_, d);
        }
    }
    files_[kDepth].exr->writeRows(band.rows, {band.depth});
}

void AovSetWriter::writeNormals(const AovBand& band) {
    std::array<std::vector<float>, 3> channels;
    for (int c = 0; c < 3; ++c) {
        channels[c].reserve(band.normals.size());
        for (const glm::vec3& normal : band.normals) {
            channels[c].push_back(normal[c]);
        }
    }
    files_[kNormal].exr->writeRows(band.rows, {channels[0], channels[1], channels[2]});
    files_[kNormal].preview->writeRows(previewRows(band.normals.size(), [&](std::size_t i) {
        Rgb rgb{};
        for (int c = 0; c < 3; ++c) {
            rgb[c] = isBackground(band.classes[i])
                         ? 0
                         : std::uint8_t(std::lround(127.5 * (double(band.normals[i][c]) + 1.0)));
        }
        return rgb;
    }));
}

void AovSetWriter::writeObjectIds(const AovBand& band) {
    std::vector<float> ids;
    ids.reserve(band.classes.size());
    for (const PixelClass& pixel : band.classes) {
        ids.push_back(isBackground(pixel) ? -1.0f : float(pixel.node));
    }
    files_[kObjectId].exr->writeRows(band.rows, {ids});
    files_[kObjectId].preview->writeRows(previewRows(ids.size(), [&](std::size_t i) {
        return isBackground(band.classes[i]) ? Rgb{0, 0, 0} : idColour(band.classes[i].node);
    }));
}

void AovSetWriter::writeLights(const AovBand& band) {
    const std::size_t margins = layout_.withMargins ? 1 : 0;
    for (std::size_t light = 0; kFirstLight + light + margins < files_.size(); ++light) {
        const std::uint32_t bit = PixelClass::litBit(std::uint32_t(light));
        std::vector<float> lit;
        lit.reserve(band.classes.size());
        for (const PixelClass& pixel : band.classes) {
            lit.push_back((pixel.flags & bit) != 0 ? 1.0f : 0.0f);
        }
        File& file = files_[kFirstLight + light];
        file.exr->writeRows(band.rows, {lit});
        file.preview->writeRows(previewRows(lit.size(), [&](std::size_t i) {
            return lit[i] != 0.0f ? Rgb{255, 255, 255} : Rgb{0, 0, 0};
        }));
    }
}

void AovSetWriter::writeMargins(const AovBand& band) {
    File& file = files_.back();
    file.exr->writeRows(band.rows, {band.margins});
    file.preview->writeRows(previewRows(band.margins.size(), [&](std::size_t i) {
        const double margin = band.margins[i];
        if (!std::isfinite(margin)) {
            return Rgb{0, 0, 0};
        }
        if (margin < layout_.ambiguityMargin) {
            return Rgb{255, 0, 0};
        }
        return ramp(std::log10(margin / layout_.ambiguityMargin) / 9.0);
    }));
}

void AovSetWriter::drawDepthPreview() {
    const std::filesystem::path depth = directory_ / "depth.exr";
    ExrRowReader reader(depth);
    PngRowWriter preview(directory_ / "depth.png", layout_.width, layout_.height, notesFor("aov depth preview"));
    // Log scale: a floor reaches to the horizon, which would flatten a linear ramp.
    const double range = farthest_ > nearest_ ? std::log(double(farthest_) / nearest_) : 1.0;
    const std::uint32_t bandRows =
        std::uint32_t(std::max<std::size_t>(1, kPreviewBandBytes / (sizeof(float) * std::max(1u, layout_.width))));
    std::vector<float> values;
    for (std::uint32_t first = 0; first < layout_.height; first += bandRows) {
        const std::uint32_t rows = std::min(bandRows, layout_.height - first);
        values.resize(std::size_t(rows) * layout_.width);
        reader.readRows("Y", first, rows, values);
        preview.writeRows(previewRows(values.size(), [&](std::size_t i) {
            return std::isfinite(values[i]) ? ramp(1.0 - std::log(double(values[i]) / nearest_) / range) : Rgb{0, 0, 0};
        }));
    }
    preview.finish();
}

std::vector<std::string> AovSetWriter::finish() {
    std::vector<std::string> names;
    for (File& file : files_) {
        file.exr->finish();
        names.push_back(file.name + ".exr");
        if (file.preview) {
            file.preview->finish();
        } else {
            drawDepthPreview();
        }
        names.push_back(file.name + ".png");
    }
    return names;
}

}  // namespace hexray::image
