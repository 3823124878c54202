#include "gpu/kernel_cache.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "gpu/stable_hash.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'H', 'X', 'K', 'E', 'R', 'N', 'L', '1'};
constexpr std::uint32_t kSpirvMagic = 0x07230203u;

// The file: kMagic, the key's length (uint64) and bytes, the SPIR-V's word count (uint64) and words.
std::string serialize(const std::string& key, std::span<const std::uint32_t> spirv) {
    std::string bytes(kMagic, sizeof kMagic);
    const auto appendCount = [&](std::uint64_t count) {
        bytes.append(reinterpret_cast<const char*>(&count), sizeof count);
    };
    appendCount(key.size());
    bytes += key;
    appendCount(spirv.size());
    bytes.append(reinterpret_cast<const char*>(spirv.data()), spirv.size_bytes());
    return bytes;
}

std::optional<std::vector<std::uint32_t>> deserialize(const std::string& bytes, const std::string& key) {
    std::size_t at = 0;
    const auto read = [&](void* into, std::size_t size) {
        if (bytes.size() - at < size) {
            return false;
        }
        std::memcpy(into, bytes.data() + at, size);
        at += size;
        return true;
    };
    char magic[sizeof kMagic];
    std::uint64_t keySize = 0;
    if (!read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !read(&keySize, sizeof keySize) ||
        keySize != key.size() || bytes.compare(at, key.size(), key) != 0) {
        return std::nullopt;
    }
    at += key.size();
    std::uint64_t words = 0;
    if (!read(&words, sizeof words) || words == 0 || (bytes.size() - at) != words * sizeof(std::uint32_t)) {
        return std::nullopt;
    }
    std::vector<std::uint32_t> spirv(words);
    read(spirv.data(), words * sizeof(std::uint32_t));
    if (spirv[0] != kSpirvMagic) {
        return std::nullopt;
    }
    return spirv;
}

}  // namespace

KernelCache::KernelCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path KernelCache::defaultDirectory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return fs::path(xdg) / "hexray";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return fs::path(home) / ".cache" / "hexray";
    }
    return {};
}

std::filesystem::path KernelCache::fileFor(const std::string& key) const {
    StableHash hash;
    hash.add(key);
    return directory_ / (hash.hex() + ".spv");
}

std::optional<std::vector<std::uint32_t>> KernelCache::load(const std::string& key) const {
    if (directory_.empty()) {
        return std::nullopt;
    }
    std::ifstream in(fileFor(key), std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return deserialize(bytes, key);
}

void KernelCache::store(const std::string& key, std::span<const std::uint32_t> spirv) const {
    if (directory_.empty()) {
        return;
    }
    std::error_code error;
    fs::create_directories(directory_, error);
    const fs::path target = fileFor(key);
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "." + string + "...".
    std::string name = ".";
    name += target.filename().string();
    name += ".XXXXXX";
    std::string temporary = (directory_ / name).string();
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) {
        return;  // an unwritable cache is no cache
    }
    const std::string bytes = serialize(key, spirv);
    const bool written = ::write(fd, bytes.data(), bytes.size()) == ssize_t(bytes.size());
    const bool closed = ::close(fd) == 0;
    if (!written || !closed || std::rename(temporary.c_str(), target.c_str()) != 0) {
        ::unlink(temporary.c_str());
    }
}

}  // namespace hexray
