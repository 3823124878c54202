#pragma once
// SHA-256 through OpenSSL's libcrypto (the EVP interface): the kernel cache's checksums and file
// names, the strips' pixel digests.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

struct evp_md_ctx_st;

namespace hexray::inline util {

using Sha256Digest = std::array<std::uint8_t, 32>;

// A digest fed in parts. Throws std::runtime_error if libcrypto fails (it has no reason to).
class Sha256 {
public:
    Sha256();
    ~Sha256();
    Sha256(Sha256&&) noexcept;
    Sha256& operator=(Sha256&&) noexcept;

    void add(std::string_view bytes);
    // The digest of everything added; the object then takes nothing more.
    Sha256Digest finish();

private:
    std::unique_ptr<evp_md_ctx_st, void (*)(evp_md_ctx_st*)> context_;
};

Sha256Digest sha256(std::string_view bytes);

// A digest as 64 lower-case hexadecimal digits.
std::string hexText(const Sha256Digest& digest);
std::string sha256Hex(std::string_view bytes);

}  // namespace hexray::util
