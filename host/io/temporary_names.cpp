#include "io/temporary_names.h"

#include <unistd.h>

#include <algorithm>
#include <random>

namespace hexray::inline io {
namespace {

constexpr std::string_view kRandomSuffix = ".XXXXXX";
constexpr std::size_t kUsualNameMax = 255;

std::size_t nameMax(const std::filesystem::path& directory) {
    const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
    return limit > 0 ? std::size_t(limit) : kUsualNameMax;
}

// `name` cut to at most `bytes` bytes without splitting a UTF-8 sequence.
std::string prefixOf(const std::string& name, std::size_t bytes) {
    if (name.size() <= bytes) {
        return name;
    }
    std::size_t end = bytes;
    while (end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) {
        --end;  // name[end] continues a character: cut before that character starts
    }
    return name.substr(0, end);
}

}  // namespace

std::string randomName(const std::string& pattern) {
    static constexpr std::string_view kCharacters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    thread_local std::mt19937_64 generator{std::random_device{}()};
    std::uniform_int_distribution<std::size_t> pick(0, kCharacters.size() - 1);
    std::string name = pattern;
    const std::size_t suffix = name.size() >= 6 ? name.size() - 6 : 0;
    for (std::size_t i = suffix; i < name.size(); ++i) {
        name[i] = kCharacters[pick(generator)];
    }
    return name;
}

std::string partialFilePattern(const std::filesystem::path& directory, const std::string& targetName) {
    const std::size_t fixed = kPartialFilePrefix.size() + kRandomSuffix.size();
    const std::size_t room = nameMax(directory) > fixed ? nameMax(directory) - fixed : 0;
    std::string name(kPartialFilePrefix);
    name += prefixOf(targetName, room);
    name += kRandomSuffix;
    return (directory / name).string();
}

}  // namespace hexray::io
