#pragma once
// Comparing two renders of the same scene: discrete (topology) disagreements, which pixels
// are honestly ambiguous, colour error metrics, and a heat map of where the colours differ.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "image/image.h"
#include "image/image_io.h"
#include "image/pixel_class.h"

namespace hexray::inline compare {

// Per-channel statistics over every channel of the pixels compared. Values are in the
// images' own units: [0, 1] for linear images (clamped first, as the output is), levels
// 0..255 for 8-bit.
struct ErrorMetrics {
    std::uint64_t pixels = 0;  // how many pixels were compared
    double maxAbs = 0;
    double meanAbs = 0;
    double rmse = 0;
    double psnr = 0;                       // dB against the unit's peak; infinite when the images are identical
    std::uint64_t pixelsOverOneLevel = 0;  // pixels with a channel off by more than 1/255 (one 8-bit level)
    double shareOverOneLevel = 0;          // that count over the pixels compared
};

// Pixels to leave out whole: empty = none, else those whose entry is true.
using PixelMask = std::vector<bool>;

// True where a margin (as the CPU reference reports them) is below `threshold`.
PixelMask marginsBelow(const std::vector<float>& margins, double threshold);

// Which parts of each pixel's class the reference could not settle (CpuRender::ambiguity);
// empty = none.
using Ambiguities = std::vector<PixelAmbiguity>;

// Every part of every pixel in `mask` ambiguous: a whole-pixel exclusion.
Ambiguities wholePixels(const PixelMask& mask);

// Throws std::invalid_argument naming both sizes when they differ.
void requireSameSize(std::uint32_t w1, std::uint32_t h1, std::uint32_t w2, std::uint32_t h2);

// Both images must have the same size (checked; throws std::invalid_argument).
ErrorMetrics compareLinear(const Image& reference, const Image& test, const PixelMask& mask = {});
ErrorMetrics compareEncoded(const Rgb8Image& reference, const Rgb8Image& test, const PixelMask& mask = {});

// How one pixel of a test render stands against the reference's, given which of the reference's
// decisions were near-tied. A difference in a near-tied part is excused, and only that: a pixel
// near-tied on a checker edge must still show the same node and lit lights. When the node itself
// is near-tied and differs, nothing else about the pixel is comparable.
struct PixelJudgement {
    enum class Mismatch { None, Node, Checker, Lights };
    Mismatch mismatch = Mismatch::None;  // in a part that is not near-tied (the first, in this order)
    bool ambiguous = false;              // some decision was near-tied
    // Left partly unchecked without a mismatch: a near-tied part differs, or the colour may
    // differ honestly (PixelAmbiguity::colour).
    bool excused = false;
    // The colour is held to the tolerance: the node is not near-tied, no near-tied part differs
    // and nothing outside the class was near-tied, so equal decisions must give equal colours.
    bool colourCompared = false;
};
PixelJudgement judgePixel(const PixelClass& reference, const PixelClass& test, const PixelAmbiguity& ambiguity);

struct TopologyComparison {
    std::uint64_t pixels = 0;
    std::uint64_t ambiguous = 0;          // where the reference had a decision too close to call
    std::uint64_t excused = 0;            // of which the comparison had to leave part unchecked
    std::uint64_t mismatches = 0;         // pixels whose class differs in a part not near-tied, of which:
    std::uint64_t nodeMismatches = 0;     //   a different node (or hit against miss)
    std::uint64_t checkerMismatches = 0;  //   the same node, a different checker cell
    std::uint64_t lightMismatches = 0;    //   the same surface, a different set of lights reaching it
    double ambiguousShare() const { return pixels ? double(ambiguous) / double(pixels) : 0.0; }
    double excusedShare() const { return pixels ? double(excused) / double(pixels) : 0.0; }
    TopologyComparison& operator+=(const TopologyComparison& band);  // counts of more pixels
    void add(const PixelJudgement& judgement);                       // one more pixel
};

TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const Ambiguities& ambiguity);
TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const PixelMask& excluded);

// A render under test against the reference: the classes on every part the reference settled,
// the colours where judgePixel says so (band by band: render_comparator.h).
struct RenderComparison {
    TopologyComparison topology;
    ErrorMetrics linear;   // colour on the linear float images
    ErrorMetrics encoded;  // colour on the 8-bit output, in levels
    // Pixels, ambiguous or not, where either render's linear colour has a channel that is NaN,
    // infinite or negative: never a rounding matter.
    std::uint64_t invalidColours = 0;
};

// Whether a linear colour can be a render's: every channel finite and >= 0.
bool isValidColour(const glm::vec3& colour);

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const Ambiguities& ambiguity, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding);
RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const PixelMask& excluded, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding);

// When a render counts as agreeing with the reference: every decision the reference settled
// matches, the colours differ only by float rounding, and few enough pixels were near-tied for
// that to mean something (a mostly ambiguous comparison proves little, whatever it finds).
struct Tolerance {
    std::uint64_t maxTopologyMismatches = 0;
    double maxSharePercent = 0.1;      // of compared pixels whose 8-bit value differs by more than one level
    double maxRmseLevels = 1.0;        // RMSE of the 8-bit output over compared pixels, in levels
    double maxAmbiguousPercent = 5.0;  // of pixels with a near-tied decision
};

// Some of a Tolerance's limits, as an expectations file or the command line sets them: each one
// given replaces the tolerance's own.
struct ToleranceChanges {
    std::optional<std::uint64_t> maxTopologyMismatches;
    std::optional<double> maxSharePercent;
    std::optional<double> maxRmseLevels;
    std::optional<double> maxAmbiguousPercent;

    Tolerance appliedTo(Tolerance tolerance) const;
    // The limits `later` gives win over these.
    void update(const ToleranceChanges& later);
};

struct Verdict {
    bool topologyOk = false;
    bool shareOk = false;
    bool rmseOk = false;
    bool ambiguousOk = false;
    bool valuesOk = false;  // no invalid colour
    bool passed() const { return topologyOk && shareOk && rmseOk && ambiguousOk && valuesOk; }
};

Verdict judge(const RenderComparison& comparison, const Tolerance& tolerance);

// Black where the 8-bit images agree; otherwise the largest channel difference on a log scale
// from dark blue (1 level) through red and yellow to white (255 levels).
Rgb8Image diffHeatMap(const Rgb8Image& reference, const Rgb8Image& test);

// Where a render disagrees with the reference, one colour per pixel (the legend, in order of
// precedence; see judgePixel): magenta = a colour that is not finite and >= 0 in either render;
// red = topology mismatch (another node, checker cell or set of lit
// lights where the reference's decision was not near-tied); blue = excused (differs only in
// near-tied decisions, or its colour is not comparable); yellow = the colour compared and more
// than one 8-bit level off; navy = a decision near-tied, the renders agreeing on it; black =
// agreement.
namespace mask_colour {
inline constexpr std::uint8_t kInvalid[3] = {255, 0, 255};
inline constexpr std::uint8_t kTopology[3] = {255, 0, 0};
inline constexpr std::uint8_t kExcused[3] = {0, 64, 255};
inline constexpr std::uint8_t kColour[3] = {255, 255, 0};
inline constexpr std::uint8_t kNearTied[3] = {0, 0, 112};
}  // namespace mask_colour
// `referenceLinear` and `testLinear`: the linear colours (for the validity of each), or empty.
Rgb8Image mismatchMask(const std::vector<PixelClass>& referenceClasses, const std::vector<PixelClass>& testClasses,
                       const Ambiguities& ambiguity, const Rgb8Image& reference, const Rgb8Image& test,
                       const Image* referenceLinear = nullptr, const Image* testLinear = nullptr);

}  // namespace hexray::compare
