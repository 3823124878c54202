#pragma once
// A linear-light RGB image in float: what both renderers produce before encoding.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace hexray::inline image {

struct Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<glm::vec3> pixels;  // row-major, (0, 0) at the top-left

    Image() = default;
    Image(std::uint32_t w, std::uint32_t h) : width(w), height(h), pixels(std::size_t(w) * h) {}

    glm::vec3& at(std::uint32_t x, std::uint32_t y) { return pixels[std::size_t(y) * width + x]; }
    const glm::vec3& at(std::uint32_t x, std::uint32_t y) const { return pixels[std::size_t(y) * width + x]; }
};

}  // namespace hexray::image
