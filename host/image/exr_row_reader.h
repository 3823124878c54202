#pragma once
// Reads a float OpenEXR file (through OpenEXR) a band of rows at a time: the AOVs' tests, and
// the depth preview, which is drawn from the finished depth file.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hexray::inline image {

class ExrRowReader {
public:
    // Throws ImageIoError naming the file when it cannot be read as OpenEXR.
    explicit ExrRowReader(const std::filesystem::path& path);
    ~ExrRowReader();
    ExrRowReader(const ExrRowReader&) = delete;
    ExrRowReader& operator=(const ExrRowReader&) = delete;

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    std::vector<std::string> channelNames() const;
    // The header's string attribute `name`.
    std::optional<std::string> stringAttribute(const std::string& name) const;

    // Rows [firstRow, firstRow + rows) of `channel`, as float, into `values` (rows × width).
    void readRows(const std::string& channel, std::uint32_t firstRow, std::uint32_t rows, std::span<float> values);

private:
    struct Decoder;
    std::unique_ptr<Decoder> decoder_;
    std::string name_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
};

}  // namespace hexray::image
