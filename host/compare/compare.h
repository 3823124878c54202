#pragma once
// Error metrics between two renders of the same scene, and a heat map of where they differ.

#include <cstdint>

#include "image/image.h"
#include "image/image_io.h"

namespace hexray {

// Per-channel statistics over every channel of every pixel. Values are in the image's own
// units: [0, 1] for linear images (clamped first, as the output is), levels 0..255 for 8-bit.
struct ErrorMetrics {
    double maxAbs = 0;
    double meanAbs = 0;
    double rmse = 0;
    double psnr = 0;           // dB against the unit's peak; infinite when the images are identical
    std::uint64_t pixelsOverOneLevel = 0;  // pixels with a channel off by more than 1/255 (one 8-bit level)
    double shareOverOneLevel = 0;          // that count over all pixels
};

struct ImageComparison {
    ErrorMetrics linear;   // on the linear float images
    ErrorMetrics encoded;  // on the 8-bit output, in levels
};

// When two renders count as the same picture. The defaults allow for the pixels where float32
// and double legitimately round a silhouette, shadow boundary or checker edge to different
// sides: the shipped scenes put whole rows and columns exactly on checker edges.
struct Tolerance {
    double maxSharePercent = 1.0;  // of pixels whose 8-bit value differs by more than one level
    double maxRmseLevels = 5.0;    // RMSE of the 8-bit output, in levels
};

struct Verdict {
    bool shareOk = false;
    bool rmseOk = false;
    bool passed() const { return shareOk && rmseOk; }
};

Verdict judge(const ImageComparison& comparison, const Tolerance& tolerance);

// Both images must have the same size (checked; throws std::invalid_argument).
ErrorMetrics compareLinear(const Image& reference, const Image& test);
ErrorMetrics compareEncoded(const Rgb8Image& reference, const Rgb8Image& test);
ImageComparison compareRenders(const Image& reference, const Image& test, Encoding encoding);

// Black where the 8-bit images agree; otherwise the largest channel difference on a log scale
// from dark blue (1 level) through red and yellow to white (255 levels).
Rgb8Image diffHeatMap(const Rgb8Image& reference, const Rgb8Image& test);

}  // namespace hexray
