#pragma once
// Comparing two renders of the same scene: discrete (topology) disagreements, which pixels
// are honestly ambiguous, colour error metrics, and a heat map of where the colours differ.

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"
#include "image/pixel_class.h"

namespace hexray {

// Per-channel statistics over every channel of the pixels compared. Values are in the
// images' own units: [0, 1] for linear images (clamped first, as the output is), levels
// 0..255 for 8-bit.
struct ErrorMetrics {
    std::uint64_t pixels = 0;  // how many pixels were compared
    double maxAbs = 0;
    double meanAbs = 0;
    double rmse = 0;
    double psnr = 0;  // dB against the unit's peak; infinite when the images are identical
    std::uint64_t pixelsOverOneLevel = 0;  // pixels with a channel off by more than 1/255 (one 8-bit level)
    double shareOverOneLevel = 0;          // that count over the pixels compared
};

// Which pixels to compare: empty = all, else those whose entry is true.
using PixelMask = std::vector<bool>;

// True where a margin (as the CPU reference reports them) is below `threshold`.
PixelMask marginsBelow(const std::vector<float>& margins, double threshold);

// Both images must have the same size (checked; throws std::invalid_argument).
ErrorMetrics compareLinear(const Image& reference, const Image& test, const PixelMask& mask = {});
ErrorMetrics compareEncoded(const Rgb8Image& reference, const Rgb8Image& test, const PixelMask& mask = {});

struct TopologyComparison {
    std::uint64_t pixels = 0;
    std::uint64_t ambiguous = 0;          // where the reference says a decision was too close to call
    std::uint64_t mismatches = 0;         // unambiguous pixels whose class differs, of which:
    std::uint64_t nodeMismatches = 0;     //   a different node (or hit against miss)
    std::uint64_t checkerMismatches = 0;  //   the same node, a different checker cell
    std::uint64_t lightMismatches = 0;    //   the same surface, a different set of lights reaching it
    double ambiguousShare() const { return pixels ? double(ambiguous) / double(pixels) : 0.0; }
    TopologyComparison& operator+=(const TopologyComparison& band);  // counts of more pixels
};

TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const PixelMask& ambiguous);

// A render under test against the reference, on the pixels the reference calls unambiguous
// (band by band: render_comparator.h).
struct RenderComparison {
    TopologyComparison topology;
    ErrorMetrics linear;   // colour on the linear float images
    ErrorMetrics encoded;  // colour on the 8-bit output, in levels
};

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const PixelMask& ambiguous, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding);

// When a render counts as agreeing with the reference. Ambiguous pixels are left out of
// everything; on the rest the discrete decisions must match exactly, and the colours may
// differ only by float rounding.
struct Tolerance {
    std::uint64_t maxTopologyMismatches = 0;
    double maxSharePercent = 0.1;  // of unambiguous pixels whose 8-bit value differs by more than one level
    double maxRmseLevels = 1.0;    // RMSE of the 8-bit output over unambiguous pixels, in levels
};

struct Verdict {
    bool topologyOk = false;
    bool shareOk = false;
    bool rmseOk = false;
    bool passed() const { return topologyOk && shareOk && rmseOk; }
};

Verdict judge(const RenderComparison& comparison, const Tolerance& tolerance);

// Black where the 8-bit images agree; otherwise the largest channel difference on a log scale
// from dark blue (1 level) through red and yellow to white (255 levels).
Rgb8Image diffHeatMap(const Rgb8Image& reference, const Rgb8Image& test);

// Where a render disagrees with the reference, one colour per pixel (the legend, in order of
// precedence): blue = ambiguous (left out of the comparison); red = topology mismatch (another
// node, checker cell or set of lit lights); yellow = same class but the 8-bit colour more than
// one level off; black = agreement.
namespace mask_colour {
inline constexpr std::uint8_t kAmbiguous[3] = {0, 64, 255};
inline constexpr std::uint8_t kTopology[3] = {255, 0, 0};
inline constexpr std::uint8_t kColour[3] = {255, 255, 0};
}  // namespace mask_colour
Rgb8Image mismatchMask(const std::vector<PixelClass>& referenceClasses, const std::vector<PixelClass>& testClasses,
                       const PixelMask& ambiguous, const Rgb8Image& reference, const Rgb8Image& test);

}  // namespace hexray
