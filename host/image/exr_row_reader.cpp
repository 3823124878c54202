#include "image/exr_row_reader.h"

#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "image/image_io.h"

namespace hexray::inline image {

struct ExrRowReader::Decoder {
    Imf::InputFile file;
    explicit Decoder(const std::filesystem::path& path) : file(path.c_str()) {}
};

ExrRowReader::ExrRowReader(const std::filesystem::path& path) : name_(path.string()) {
    try {
        decoder_ = std::make_unique<Decoder>(path);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& error) {
        throw ImageIoError(name_ + ": cannot read OpenEXR: " + error.what());
    }
    const Imath::Box2i window = decoder_->file.header().dataWindow();
    width_ = std::uint32_t(window.max.x - window.min.x + 1);
    height_ = std::uint32_t(window.max.y - window.min.y + 1);
}

ExrRowReader::~ExrRowReader() = default;

std::vector<std::string> ExrRowReader::channelNames() const {
    std::vector<std::string> names;
    const Imf::ChannelList& channels = decoder_->file.header().channels();
    for (auto channel = channels.begin(); channel != channels.end(); ++channel) {
        names.emplace_back(channel.name());
    }
    return names;
}

std::optional<std::string> ExrRowReader::stringAttribute(const std::string& name) const {
    const auto* attribute = decoder_->file.header().findTypedAttribute<Imf::StringAttribute>(name);
    return attribute ? std::optional<std::string>(attribute->value()) : std::nullopt;
}

void ExrRowReader::readRows(const std::string& channel, std::uint32_t firstRow, std::uint32_t rows,
                            std::span<float> values) {
    if (firstRow + rows > height_ || values.size() != std::size_t(rows) * width_) {
        throw std::invalid_argument("ExrRowReader::readRows: rows outside the image or the wrong buffer size");
    }
    const Imath::V2i origin = decoder_->file.header().dataWindow().min;
    const int y = origin.y + int(firstRow);
    Imf::FrameBuffer frame;
    frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, values.data(), Imath::V2i(origin.x, y), width_, rows));
    try {
        decoder_->file.setFrameBuffer(frame);
        decoder_->file.readPixels(y, y + int(rows) - 1);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& error) {
        throw ImageIoError(name_ + ": cannot read OpenEXR: " + error.what());
    }
}

}  // namespace hexray::image
