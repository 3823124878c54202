#pragma once
// Error metrics gathered one pixel at a time, so images can be compared band by band.

#include <cstdint>

#include <glm/vec3.hpp>

#include "compare/compare.h"

namespace hexray::inline compare {

class ErrorAccumulator {
public:
    // `oneLevel` and `peak` are in the images' units (1/255 and 1 for linear images; 1 and 255
    // for 8-bit ones).
    ErrorAccumulator(double oneLevel, double peak) : oneLevel_(oneLevel), peak_(peak) {}

    // One pixel's per-channel difference, test minus reference.
    void addPixel(const glm::dvec3& difference);

    ErrorMetrics result() const;

private:
    double oneLevel_;
    double peak_;
    ErrorMetrics metrics_;
    double sumAbs_ = 0;
    double sumSquares_ = 0;
    std::uint64_t pixels_ = 0;
};

// A linear pixel's difference as the output shows it: both clamped to [0, 1] first.
glm::dvec3 displayedDifference(const glm::vec3& reference, const glm::vec3& test);

// Pixel `pixel`'s difference in 8-bit levels.
glm::dvec3 levelDifference(const Rgb8Image& reference, const Rgb8Image& test, std::size_t pixel);

}  // namespace hexray::compare
