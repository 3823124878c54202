#include "image/exr_io.h"

#include <span>

#include "image/exr_row_reader.h"
#include "image/exr_row_writer.h"

namespace hexray::inline image {

void writeExr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
              const std::vector<ExrChannel>& channels) {
    std::vector<std::string> names;
    std::vector<std::span<const float>> values;
    for (const ExrChannel& channel : channels) {
        names.push_back(channel.name);
        values.emplace_back(channel.values);
    }
    ExrRowWriter writer(path, width, height, names);
    writer.writeRows(height, values);
    writer.finish();
}

ExrImage readExr(const std::filesystem::path& path) {
    ExrRowReader reader(path);
    ExrImage image{reader.width(), reader.height(), {}};
    for (const std::string& name : reader.channelNames()) {
        std::vector<float>& values = image.channels[name];
        values.resize(std::size_t(image.width) * image.height);
        reader.readRows(name, 0, image.height, values);
    }
    return image;
}

}  // namespace hexray::image
