#include "kernels/kernel_cache_entry.h"

#include <cstring>
#include <optional>

#include "kernels/spirv_validation.h"
#include "util/sha256.h"

namespace hexray::inline kernels {
namespace {

void appendCount(std::string& bytes, std::uint64_t count) {
    bytes.append(reinterpret_cast<const char*>(&count), sizeof count);
}

// Reads the body after the checksum, in order, never past its end.
class BodyReader {
public:
    explicit BodyReader(std::string_view body) : body_(body) {}
    std::optional<std::uint64_t> count() {
        std::uint64_t value = 0;
        if (left() < sizeof value) {
            return std::nullopt;
        }
        std::memcpy(&value, body_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    std::string_view take(std::uint64_t size) {
        const std::string_view bytes = body_.substr(at_, std::size_t(size));
        at_ += bytes.size();
        return bytes;
    }
    std::size_t left() const { return body_.size() - at_; }

private:
    std::string_view body_;
    std::size_t at_ = 0;
};

KernelCacheEntry refused(std::string problem) {
    return KernelCacheEntry{{}, std::move(problem)};
}

}  // namespace

std::string sealKernelCacheEntry(const std::string& key, std::span<const std::uint32_t> spirv) {
    std::string body;
    appendCount(body, key.size());
    body += key;
    appendCount(body, spirv.size());
    body.append(reinterpret_cast<const char*>(spirv.data()), spirv.size_bytes());
    const Sha256Digest digest = sha256(body);
    std::string bytes(kKernelCacheMagic);
    bytes.append(reinterpret_cast<const char*>(digest.data()), digest.size());
    return bytes + body;
}

KernelCacheEntry openKernelCacheEntry(std::string_view bytes, const std::string& key) {
    if (bytes.size() < kKernelCacheBodyOffset || bytes.substr(0, kKernelCacheMagic.size()) != kKernelCacheMagic) {
        return refused("not a kernel cache file of this hexray (no " + std::string(kKernelCacheMagic) + " header)");
    }
    const std::string_view body = bytes.substr(kKernelCacheBodyOffset);
    const Sha256Digest digest = sha256(body);
    if (std::memcmp(digest.data(), bytes.data() + kKernelCacheDigestOffset, digest.size()) != 0) {
        return refused("its SHA-256 checksum does not match its contents");
    }
    BodyReader reader(body);
    const std::optional<std::uint64_t> keySize = reader.count();
    if (!keySize || *keySize != key.size() || reader.take(*keySize) != key) {
        return refused("it holds another kernel's key");
    }
    const std::optional<std::uint64_t> words = reader.count();
    if (!words || *words == 0 || *words != reader.left() / sizeof(std::uint32_t) ||
        reader.left() % sizeof(std::uint32_t) != 0) {
        return refused("its SPIR-V's length does not match the file's");
    }
    KernelCacheEntry entry;
    entry.spirv.resize(std::size_t(*words));
    const std::string_view spirvBytes = reader.take(*words * sizeof(std::uint32_t));
    std::memcpy(entry.spirv.data(), spirvBytes.data(), spirvBytes.size());
    if (const std::optional<std::string> problem = spirvValidationProblem(entry.spirv)) {
        return refused("its SPIR-V fails validation: " + *problem);
    }
    return entry;
}

}  // namespace hexray::kernels
