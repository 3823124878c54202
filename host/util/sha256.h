#pragma once
// SHA-256 through OpenSSL's libcrypto (the EVP interface): the kernel cache's checksums and file
// names.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace hexray {

using Sha256Digest = std::array<std::uint8_t, 32>;

// Throws std::runtime_error if libcrypto fails (it has no reason to).
Sha256Digest sha256(std::string_view bytes);

// The digest as 64 lower-case hexadecimal digits.
std::string sha256Hex(std::string_view bytes);

}  // namespace hexray
