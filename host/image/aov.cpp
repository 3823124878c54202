#include "image/aov.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>

#include "image/exr_io.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

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
        case 0: rgb = {1, x, 0}; break;
        case 1: rgb = {x, 1, 0}; break;
        case 2: rgb = {0, 1, x}; break;
        case 3: rgb = {0, x, 1}; break;
        case 4: rgb = {x, 0, 1}; break;
        default: rgb = {1, 0, x}; break;
    }
    return {std::uint8_t(55 + 200 * rgb[0]), std::uint8_t(55 + 200 * rgb[1]), std::uint8_t(55 + 200 * rgb[2])};
}

// Whether `name` is a file an AOV set may hold: depth, normal, object-id, margin or light-N,
// as .exr or .png.
bool isAovFileName(const std::filesystem::path& name) {
    const std::string extension = name.extension().string();
    const std::string stem = name.stem().string();
    if (extension != ".exr" && extension != ".png") {
        return false;
    }
    if (stem == "depth" || stem == "normal" || stem == "object-id" || stem == "margin") {
        return true;
    }
    const std::string light = "light-";
    return stem.size() > light.size() && stem.compare(0, light.size(), light) == 0 &&
           std::all_of(stem.begin() + light.size(), stem.end(), [](unsigned char c) { return std::isdigit(c); });
}

template <class PixelColour>
Rgb8Image preview(const AovSet& aovs, PixelColour&& colour) {
    Rgb8Image image{aovs.width, aovs.height, {}};
    image.bytes.reserve(std::size_t(aovs.width) * aovs.height * 3);
    for (std::size_t i = 0; i < std::size_t(aovs.width) * aovs.height; ++i) {
        const Rgb rgb = colour(i);
        image.bytes.insert(image.bytes.end(), rgb.begin(), rgb.end());
    }
    return image;
}

// Writes every AOV of `aovs` into `into`, appending the file names to `names`.
void writeSet(const std::filesystem::path& into, const AovSet& aovs, std::vector<std::string>& names) {
    const std::size_t count = std::size_t(aovs.width) * aovs.height;
    const auto write = [&](const std::string& name, std::vector<ExrChannel> channels, const Rgb8Image& image) {
        writeExr(into / (name + ".exr"), aovs.width, aovs.height, std::move(channels));
        writePng(into / (name + ".png"), image);
        names.push_back(name + ".exr");
        names.push_back(name + ".png");
    };
    const auto background = [&](std::size_t i) { return aovs.classes[i].node == PixelClass::kBackground; };

    float nearest = std::numeric_limits<float>::infinity();
    float farthest = 0.0f;
    for (float d : aovs.depth) {
        if (std::isfinite(d)) {
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        }
    }
    write("depth", {{"Y", aovs.depth}}, preview(aovs, [&](std::size_t i) {
              if (!std::isfinite(aovs.depth[i])) {
                  return Rgb{0, 0, 0};
              }
              // Log scale: a floor reaches to the horizon, which would flatten a linear ramp.
              const double range = farthest > nearest ? std::log(double(farthest) / nearest) : 1.0;
              return ramp(1.0 - std::log(double(aovs.depth[i]) / nearest) / range);
          }));

    std::array<std::vector<float>, 3> normal;
    for (int c = 0; c < 3; ++c) {
        normal[c].resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            normal[c][i] = aovs.normals[i][c];
        }
    }
    write("normal", {{"R", normal[0]}, {"G", normal[1]}, {"B", normal[2]}}, preview(aovs, [&](std::size_t i) {
              Rgb rgb{};
              for (int c = 0; c < 3; ++c) {
                  rgb[c] = background(i) ? 0 : std::uint8_t(std::lround(127.5 * (double(aovs.normals[i][c]) + 1.0)));
              }
              return rgb;
          }));

    std::vector<float> ids(count);
    for (std::size_t i = 0; i < count; ++i) {
        ids[i] = background(i) ? -1.0f : float(aovs.classes[i].node);
    }
    write("object-id", {{"Y", ids}},
          preview(aovs, [&](std::size_t i) { return background(i) ? Rgb{0, 0, 0} : idColour(aovs.classes[i].node); }));

    for (std::size_t light = 0; light < std::min<std::size_t>(aovs.lightCount, PixelClass::kClassifiedLights); ++light) {
        const std::uint32_t bit = PixelClass::litBit(std::uint32_t(light));
        std::vector<float> lit(count);
        for (std::size_t i = 0; i < count; ++i) {
            lit[i] = (aovs.classes[i].flags & bit) != 0 ? 1.0f : 0.0f;
        }
        write("light-" + std::to_string(light), {{"Y", lit}}, preview(aovs, [&](std::size_t i) {
                  return lit[i] != 0.0f ? Rgb{255, 255, 255} : Rgb{0, 0, 0};
              }));
    }

    if (aovs.margins) {
        const std::vector<float>& margins = *aovs.margins;
        write("margin", {{"Y", margins}}, preview(aovs, [&](std::size_t i) {
                  if (!std::isfinite(margins[i])) {
                      return Rgb{0, 0, 0};
                  }
                  if (margins[i] < aovs.ambiguityMargin) {
                      return Rgb{255, 0, 0};
                  }
                  return ramp((std::log10(std::max(double(margins[i]), 1e-12)) + 12.0) / 12.0);
              }));
    }
}

void removeQuietly(const std::filesystem::path& directory) {
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
}

}  // namespace

StagedAovs::StagedAovs(const std::filesystem::path& directory, const AovSet& aovs) : directory_(directory) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) {
        throw ImageIoError(directory.string() + ": cannot create the AOV directory: " + error.message());
    }
    // Inside the target directory, so that commit() renames within one file system.
    std::string pattern = (directory / ".hexray-aov-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
        throw ImageIoError(directory.string() + ": cannot create a staging directory: " +
                           std::generic_category().message(errno));
    }
    staging_ = pattern;
    try {
        writeSet(staging_, aovs, names_);
    } catch (...) {
        removeQuietly(staging_);  // a constructor that throws gets no destructor call
        throw;
    }
}

StagedAovs::~StagedAovs() {
    if (!staging_.empty()) {
        removeQuietly(staging_);
    }
}

std::vector<std::filesystem::path> StagedAovs::commit() {
    std::error_code error;
    std::vector<std::filesystem::path> committed;
    for (const std::string& name : names_) {
        std::filesystem::rename(staging_ / name, directory_ / name, error);
        if (error) {
            throw ImageIoError((directory_ / name).string() + ": cannot move the AOV into place: " + error.message());
        }
        committed.push_back(directory_ / name);
    }
    removeQuietly(staging_);
    staging_.clear();
    // Then an earlier set's files that this one did not replace: its extra lights, its margin.
    for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
        const std::string name = entry.path().filename().string();
        if (isAovFileName(name) && std::find(names_.begin(), names_.end(), name) == names_.end()) {
            std::filesystem::remove(entry.path(), error);
            if (error) {
                throw ImageIoError(entry.path().string() + ": cannot remove an earlier AOV: " + error.message());
            }
        }
    }
    if (error) {
        throw ImageIoError(directory_.string() + ": cannot list the AOV directory: " + error.message());
    }
    return committed;
}

}  // namespace hexray
