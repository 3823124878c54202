#pragma once
// Float OpenEXR files (through Debian's tinyexr): the AOVs `render --aov` writes, and reading
// them back (tests).

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hexray {

struct ExrChannel {
    std::string name;           // e.g. "Y", or "R", "G", "B"
    std::vector<float> values;  // width * height, row-major, (0, 0) at the top-left
};

// 32-bit float channels, ZIP-compressed. Atomic like the PNGs (atomic_file.h); throws
// ImageIoError naming the file.
void writeExr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
              std::vector<ExrChannel> channels);

struct ExrImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::map<std::string, std::vector<float>> channels;
};

ExrImage readExr(const std::filesystem::path& path);

}  // namespace hexray
