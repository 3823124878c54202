#pragma once
// The SHA-256 (OpenSSL's libcrypto) of an image's pixels as values, whatever the file's
// encoding: 8-bit RGB rows as their bytes; float RGB rows as each pixel's R, G, B in IEEE 754
// binary32, little-endian. A preamble (a strip's stamp) hashed first binds other text to the
// pixels. A writer and a reader that hash the same rows in order agree, whatever bands they use.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/sha256.h"

namespace hexray::inline image {

inline constexpr std::size_t kPixelDigestHexLength = 64;

class PixelDigest {
public:
    // Hashes `preamble` and a NUL byte.
    explicit PixelDigest(std::string_view preamble);

    void addRgb8Rows(std::span<const std::uint8_t> rgbRows);
    // Rows of `width` pixels, one plane a channel.
    void addFloatRows(std::span<const float> red, std::span<const float> green, std::span<const float> blue);
    // The digest, 64 lowercase hex digits; the digest is finished and takes no more rows.
    std::string hex();

private:
    Sha256 hash_;
    std::vector<std::uint8_t> bytes_;  // float rows in their hashed form, reused
};

}  // namespace hexray::image
