#pragma once
// FLIP, the perceptual difference of two images seen alternating (flipped) at a given viewing
// distance: Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020
// (LDR-FLIP), and "Visualizing Errors in Rendered High Dynamic Range Images", Eurographics 2021
// (HDR-FLIP). Each pixel's value is in [0, 1]: 0 where the two cannot be told apart. Written from
// the papers, and checked against NVlabs' reference implementation (docs/diff.md gives the figures).

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"

namespace hexray::inline compare {

// Pixels per degree of visual angle for a monitor `widthMetres` wide showing `widthPixels`
// pixels across, seen from `distanceMetres`.
double pixelsPerDegree(double distanceMetres, double widthPixels, double widthMetres);

// The papers' (and the reference implementation's) default viewing condition: a 0.7 m wide
// 3840-pixel monitor seen from 0.7 m, about 67.02 pixels per degree.
inline const double kDefaultPixelsPerDegree = pixelsPerDegree(0.7, 3840.0, 0.7);

// One FLIP value a pixel, row-major.
struct FlipMap {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> values;

    double mean() const;
    double max() const;
};

// LDR-FLIP of two images in linear RGB, each channel clamped to [0, 1] first. Both images must
// have the same size (throws std::invalid_argument).
FlipMap ldrFlip(const Image& reference, const Image& test, double pixelsPerDegree);

// LDR-FLIP of two 8-bit sRGB images (a PNG's pixels), decoded to linear first.
FlipMap ldrFlip(const Rgb8Image& reference, const Rgb8Image& test, double pixelsPerDegree);

// The exposures HDR-FLIP views both images at: `count` evenly spaced from `start` to `stop`
// (in stops, each a factor of 2), chosen from the reference so that its brightest pixel and its
// median pixel each reach 85% of the tone mapper's white at one end.
struct FlipExposures {
    double start = 0;
    double stop = 0;
    int count = 2;
};
FlipExposures hdrFlipExposures(const Image& reference);

// HDR-FLIP: at each exposure both linear images are scaled, tone mapped (ACES, as the papers
// fit it) and clamped, and compared by LDR-FLIP; each pixel keeps its largest value. A channel
// that is not finite, or negative, counts as 0.
FlipMap hdrFlip(const Image& reference, const Image& test, double pixelsPerDegree, const FlipExposures& exposures);
FlipMap hdrFlip(const Image& reference, const Image& test, double pixelsPerDegree);

// A FLIP map as a heat map: black (0) through purple and orange to pale yellow (1).
Rgb8Image flipHeatMap(const FlipMap& map);

}  // namespace hexray::compare
