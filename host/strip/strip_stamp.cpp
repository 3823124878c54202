#include "strip/strip_stamp.h"

#include <algorithm>
#include <cstdio>

#include "util/stable_hash.h"
#include "scene/scene.h"

namespace hexray::inline strip {
namespace {

// What sceneTextIdentity writes: 16 hex digits, '/', a decimal size.
bool isSceneIdentity(const std::string& text) {
    const auto hex = [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); };
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    return text.size() > 17 && std::all_of(text.begin(), text.begin() + 16, hex) && text[16] == '/' &&
           std::all_of(text.begin() + 17, text.end(), digit);
}

// A version as CMake and git give it: printable, without the separator ';'.
bool isVersion(const std::string& text) {
    return !text.empty() && text.size() <= 200 &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= ' ' && c <= '~' && c != ';'; });
}

std::string imageSize(std::uint64_t width, std::uint64_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

bool StripStamp::sameImage(const StripStamp& other) const {
    return strip.count == other.strip.count && width == other.width && height == other.height &&
           samplesPerPixel == other.samplesPerPixel && renderer == other.renderer && scene == other.scene &&
           version == other.version;
}

std::string formatStripStamp(const StripStamp& stamp) {
    const RowRange rows = stamp.rows();
    char head[160];
    std::snprintf(head, sizeof head, "%u/%u rows %u-%u of %ux%u; spp %u; ", stamp.strip.index, stamp.strip.count,
                  rows.first, rows.end() - 1, stamp.width, stamp.height, stamp.samplesPerPixel);
    return head + stamp.renderer + "; scene " + stamp.scene + "; hexray " + stamp.version;
}

std::optional<StripStamp> parseStripStamp(const std::string& text) {
    StripStamp stamp;
    unsigned first = 0;
    unsigned last = 0;
    int rendererStart = -1;
    const int read =
        std::sscanf(text.c_str(), "%u/%u rows %u-%u of %ux%u; spp %u; %n", &stamp.strip.index, &stamp.strip.count,
                    &first, &last, &stamp.width, &stamp.height, &stamp.samplesPerPixel, &rendererStart);
    const std::size_t versionAt = text.rfind("; hexray ");
    const std::size_t sceneAt = versionAt == std::string::npos ? versionAt : text.rfind("; scene ", versionAt);
    if (read != 7 || rendererStart < 0 || sceneAt == std::string::npos || sceneAt < std::size_t(rendererStart) ||
        stamp.strip.count == 0 || stamp.strip.index >= stamp.strip.count || stamp.strip.count > stamp.height) {
        return std::nullopt;
    }
    stamp.renderer = text.substr(std::size_t(rendererStart), sceneAt - std::size_t(rendererStart));
    stamp.scene = text.substr(sceneAt + 8, versionAt - sceneAt - 8);
    stamp.version = text.substr(versionAt + 9);
    if (!isSceneIdentity(stamp.scene) || !isVersion(stamp.version)) {
        return std::nullopt;
    }
    // Strict: anything formatStripStamp would not write (other rows, extra text) is not a stamp.
    if (formatStripStamp(stamp) != text) {
        return std::nullopt;
    }
    return stamp;
}

std::optional<std::string> beyondRendererLimits(const StripStamp& stamp) {
    if (stamp.width < 1 || stamp.height < 1 || stamp.width > kMaxImageDimension || stamp.height > kMaxImageDimension) {
        return "its stamp declares a " + imageSize(stamp.width, stamp.height) + " image, " +
               (stamp.width < 1 || stamp.height < 1 ? "which has no pixels" : "larger than hexray renders") +
               " (at most " + imageSize(kMaxImageDimension, kMaxImageDimension) + ")";
    }
    const std::uint64_t samples = std::uint64_t(stamp.width) * stamp.height * stamp.samplesPerPixel;
    if (stamp.samplesPerPixel < 1 || stamp.samplesPerPixel > kMaxSamplesPerPixel || samples > kMaxImageSamples) {
        return "its stamp declares " + imageSize(stamp.width, stamp.height) + " pixels at spp " +
               std::to_string(stamp.samplesPerPixel) + ", more samples than hexray renders (spp at most " +
               std::to_string(kMaxSamplesPerPixel) + ", " + std::to_string(kMaxImageSamples) + " samples an image)";
    }
    return std::nullopt;
}

std::string sceneTextIdentity(std::string_view text) {
    StableHash hash;
    hash.add(text);
    return hash.hex() + "/" + std::to_string(text.size());
}

}  // namespace hexray::strip
