#pragma once
// The mean LDR-FLIP (compare/flip.h) of two renders' 8-bit outputs, gathered band by band as
// `compare` receives them. FLIP filters across rows, so unlike the other metrics it needs both
// images whole (6 bytes a pixel, and FLIP's own float planes, about a hundred bytes a pixel while
// it runs), so it is measured only up to kMaxFlipPixels, 2560x1440 and a little more: past that,
// no figure, and compare's memory still grows with the width alone.

#include <cstdint>
#include <optional>

#include "image/image_io.h"
#include "scene/scene.h"

namespace hexray::inline compare {

inline constexpr std::uint64_t kMaxFlipPixels = std::uint64_t{4} << 20;

class BandFlip {
public:
    BandFlip(std::uint32_t width, std::uint32_t height, Encoding encoding);
    void add(const Rgb8Image& reference, const Rgb8Image& test);
    // At the default viewing condition (kDefaultPixelsPerDegree); nullopt for an image past the bound.
    std::optional<double> mean() const;

private:
    bool kept_;
    Encoding encoding_;
    Rgb8Image reference_;
    Rgb8Image test_;
};

}  // namespace hexray::compare
