#include "util/sha256.h"

#include <cstdio>
#include <stdexcept>

#include <openssl/evp.h>

namespace hexray {

Sha256Digest sha256(std::string_view bytes) {
    Sha256Digest digest{};
    unsigned int size = 0;
    if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &size, EVP_sha256(), nullptr) != 1 ||
        size != digest.size()) {
        throw std::runtime_error("SHA-256 failed (OpenSSL's EVP_Digest)");
    }
    return digest;
}

std::string sha256Hex(std::string_view bytes) {
    std::string hex;
    for (const std::uint8_t byte : sha256(bytes)) {
        char pair[3];
        std::snprintf(pair, sizeof pair, "%02x", byte);
        hex += pair;
    }
    return hex;
}

}  // namespace hexray
