#pragma once
// What a piece of a render in strips records about itself (a PNG text chunk or an OpenEXR string
// attribute named kStripStampKey), so that `hexray merge` can check that pieces make one image:
//   3/8 rows 180-239 of 640x480; spp 4; gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); scene 5f0c3e2a9b1d4c77/1187; hexray 0.1.0 (git 9317900a2b4c)
// Pieces of one image have the same stamp but for the strip's index and rows. Beside it, under
// kStripDigestKey, the piece records the SHA-256 of the stamp and its pixels (image/pixel_digest.h),
// written after the pixels (a PNG text chunk after them; in an OpenEXR header, a placeholder
// replaced once they are written): what merge reads is then proven to be what was rendered.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "strip/strip.h"

namespace hexray::inline strip {

inline constexpr const char* kStripStampKey = "hexray-strip";
inline constexpr const char* kStripDigestKey = "hexray-strip-sha256";

struct StripStamp {
    Strip strip;
    std::uint32_t width = 0;  // the whole image's
    std::uint32_t height = 0;
    std::uint32_t samplesPerPixel = 1;
    std::string renderer;  // "gpu f32 on <device>" or "cpu reference": another renderer, other pixels
    std::string scene;     // the scene file's identity (sceneTextIdentity)
    std::string version;   // hexray's, as `hexray --version` gives it: another build may render other pixels

    RowRange rows() const { return stripRows(strip, height); }
    // Whether `other` is a strip of the same image (any index).
    bool sameImage(const StripStamp& other) const;
};

std::string formatStripStamp(const StripStamp& stamp);

// nullopt unless `text` is exactly what formatStripStamp writes for some stamp.
std::optional<StripStamp> parseStripStamp(const std::string& text);

// Why the renderer could not have made the image `stamp` describes ("its stamp declares a
// 20000x20000 image, larger than hexray renders (at most 16384x16384)"), or nullopt.
std::optional<std::string> beyondRendererLimits(const StripStamp& stamp);

// A scene file's text as "<64-bit FNV-1a in hex>/<size in bytes>".
std::string sceneTextIdentity(std::string_view text);

}  // namespace hexray::strip
