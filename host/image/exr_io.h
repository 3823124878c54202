#pragma once
// Whole float OpenEXR files, through ExrRowWriter and ExrRowReader: small images in the tests,
// and reading AOVs back.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hexray::inline image {

struct ExrChannel {
    std::string name;           // e.g. "Y", or "R", "G", "B"
    std::vector<float> values;  // width * height, row-major, (0, 0) at the top-left
};

// 32-bit float channels, ZIP-compressed; atomic (see io/output_file.h). Throws OutputError
// naming the file when it cannot be written.
void writeExr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
              const std::vector<ExrChannel>& channels);

struct ExrImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::map<std::string, std::vector<float>> channels;
};

// Throws ImageIoError naming the file.
ExrImage readExr(const std::filesystem::path& path);

}  // namespace hexray::image
