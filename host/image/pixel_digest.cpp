#include "image/pixel_digest.h"

#include <bit>
#include <new>
#include <stdexcept>

#include <openssl/evp.h>

namespace hexray {
namespace {

void check(int openSslResult) {
    if (openSslResult != 1) {
        throw std::runtime_error("SHA-256 (OpenSSL) failed");
    }
}

}  // namespace

PixelDigest::PixelDigest(std::string_view preamble) : context_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
    if (!context_) {
        throw std::bad_alloc();
    }
    check(EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr));
    check(EVP_DigestUpdate(context_.get(), preamble.data(), preamble.size()));
    check(EVP_DigestUpdate(context_.get(), "", 1));
}

PixelDigest::~PixelDigest() = default;
PixelDigest::PixelDigest(PixelDigest&&) noexcept = default;
PixelDigest& PixelDigest::operator=(PixelDigest&&) noexcept = default;

void PixelDigest::addRgb8Rows(std::span<const std::uint8_t> rgbRows) {
    check(EVP_DigestUpdate(context_.get(), rgbRows.data(), rgbRows.size()));
}

void PixelDigest::addFloatRows(std::span<const float> red, std::span<const float> green,
                               std::span<const float> blue) {
    if (green.size() != red.size() || blue.size() != red.size()) {
        throw std::invalid_argument("PixelDigest::addFloatRows: channels of different sizes");
    }
    bytes_.resize(red.size() * 12);
    std::uint8_t* out = bytes_.data();
    const auto put = [&out](float value) {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 0; shift < 32; shift += 8) {
            *out++ = std::uint8_t(bits >> shift);
        }
    };
    for (std::size_t i = 0; i < red.size(); ++i) {
        put(red[i]);
        put(green[i]);
        put(blue[i]);
    }
    check(EVP_DigestUpdate(context_.get(), bytes_.data(), bytes_.size()));
}

std::string PixelDigest::hex() {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    check(EVP_DigestFinal_ex(context_.get(), digest, &length));
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    for (unsigned int i = 0; i < length; ++i) {
        text += kDigits[digest[i] >> 4];
        text += kDigits[digest[i] & 15];
    }
    return text;
}

}  // namespace hexray
