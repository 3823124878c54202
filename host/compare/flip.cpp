#include "compare/flip.h"

#include "compare/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

namespace hexray::inline compare {

namespace {

// The HPG 2020 paper's constants: the colour error's exponent (qc) and its remapping (pc, pt),
// the feature error's exponent (qf), and the width of the feature detectors in degrees.
constexpr float kColourExponent = 0.7f;
constexpr float kColourCut = 0.4f;
constexpr float kColourCutValue = 0.95f;
constexpr float kFeatureExponent = 0.5f;
constexpr float kFeatureWidthDegrees = 0.082f;

// The contrast sensitivity of each opponent channel (achromatic, red-green, blue-yellow) as a sum
// of two Gaussians in frequency, a * exp(-b f^2); the paper's Table 1.
struct ContrastSensitivity {
    float a1, b1, a2, b2;
};
constexpr std::array<ContrastSensitivity, 3> kSensitivity = {{
    {1.0f, 0.0047f, 0.0f, 1.0e-5f},
    {1.0f, 0.0053f, 0.0f, 1.0e-5f},
    {34.1f, 0.04f, 13.5f, 0.025f},
}};
constexpr float kLargestSensitivityScale = 0.04f;

// A single-channel image.
struct Plane {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> values;
    Plane(std::uint32_t w, std::uint32_t h) : width(w), height(h), values(std::size_t(w) * h, 0.0f) {}
};

// Linear sRGB to CIE XYZ, from the sRGB primaries and D65 white point (IEC 61966-2-1).
glm::dmat3 linearRgbToXyzMatrix() {
    const auto column = [](double x, double y) { return glm::dvec3(x / y, 1.0, (1.0 - x - y) / y); };
    const glm::dmat3 primaries(column(0.64, 0.33), column(0.30, 0.60), column(0.15, 0.06));
    const glm::dvec3 scale = glm::inverse(primaries) * column(0.3127, 0.3290);
    return glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
}

struct ColourSpace {
    glm::mat3 toXyz;
    glm::mat3 toLinearRgb;
    glm::vec3 white;  // D65 in XYZ, Y = 1
    ColourSpace()
        : toXyz(linearRgbToXyzMatrix()),
          toLinearRgb(glm::inverse(linearRgbToXyzMatrix())),
          white(linearRgbToXyzMatrix() * glm::dvec3(1.0)) {}
};
const ColourSpace& colourSpace() {
    static const ColourSpace space;
    return space;
}

// The linearised CIELab of Flohr et al. (YCxCz): opponent channels in which filtering is linear.
glm::vec3 linearRgbToYcxcz(const glm::vec3& rgb) {
    const glm::vec3 xyz = colourSpace().toXyz * rgb / colourSpace().white;
    return {116.0f * xyz.y - 16.0f, 500.0f * (xyz.x - xyz.y), 200.0f * (xyz.y - xyz.z)};
}

glm::vec3 ycxczToLinearRgb(const glm::vec3& ycxcz) {
    const float y = (ycxcz.x + 16.0f) / 116.0f;
    const glm::vec3 xyz(y + ycxcz.y / 500.0f, y, y - ycxcz.z / 200.0f);
    return colourSpace().toLinearRgb * (xyz * colourSpace().white);
}

float labCurve(float t) {
    constexpr float delta = 6.0f / 29.0f;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// CIELab with the Hunt effect folded in (chroma scaled by lightness / 100), as FLIP compares it.
glm::vec3 linearRgbToHuntLab(const glm::vec3& rgb) {
    const glm::vec3 xyz = colourSpace().toXyz * rgb / colourSpace().white;
    const float fy = labCurve(xyz.y);
    const float lightness = 116.0f * fy - 16.0f;
    const float a = 500.0f * (labCurve(xyz.x) - fy);
    const float b = 200.0f * (fy - labCurve(xyz.z));
    return {lightness, 0.01f * lightness * a, 0.01f * lightness * b};
}

// HyAB: city-block distance in lightness, Euclidean in the chromatic plane.
float hyab(const glm::vec3& p, const glm::vec3& q) {
    return std::abs(p.x - q.x) + std::hypot(p.y - q.y, p.z - q.z);
}

// The largest colour difference, between green and blue, raised to qc: the end of the scale.
float largestColourDifference() {
    return std::pow(hyab(linearRgbToHuntLab({0, 1, 0}), linearRgbToHuntLab({0, 0, 1})), kColourExponent);
}

// Taps of a 1D filter, centred: 2 * radius + 1 of them.
using Taps = std::vector<float>;

// Rows filtered by `taps`, the image's edge pixels repeated beyond it.
Plane filterRows(const Plane& in, const Taps& taps) {
    const std::size_t radius = taps.size() / 2;
    Plane out(in.width, in.height);
    std::vector<float> padded(in.width + 2 * radius);
    for (std::uint32_t y = 0; y < in.height; ++y) {
        const float* row = &in.values[std::size_t(y) * in.width];
        std::fill_n(padded.begin(), radius, row[0]);
        std::copy_n(row, in.width, padded.begin() + std::ptrdiff_t(radius));
        std::fill_n(padded.begin() + std::ptrdiff_t(radius + in.width), radius, row[in.width - 1]);
        float* target = &out.values[std::size_t(y) * in.width];
        for (std::size_t k = 0; k < taps.size(); ++k) {
            for (std::uint32_t x = 0; x < in.width; ++x) {
                target[x] += taps[k] * padded[x + k];
            }
        }
    }
    return out;
}

// Columns filtered by `taps`, the edge rows repeated beyond the image.
Plane filterColumns(const Plane& in, const Taps& taps) {
    const long radius = long(taps.size() / 2);
    Plane out(in.width, in.height);
    for (long y = 0; y < long(in.height); ++y) {
        float* target = &out.values[std::size_t(y) * in.width];
        for (long k = -radius; k <= radius; ++k) {
            const long source = std::clamp(y + k, 0L, long(in.height) - 1);
            const float* row = &in.values[std::size_t(source) * in.width];
            const float weight = taps[std::size_t(k + radius)];
            for (std::uint32_t x = 0; x < in.width; ++x) {
                target[x] += weight * row[x];
            }
        }
    }
    return out;
}

// The spatial filter of one opponent channel: the contrast sensitivity's inverse Fourier
// transform, a sum of 2D Gaussians a sqrt(pi / b) exp(-pi^2 r^2 / b) in degrees, normalised to
// sum to 1 over its square. Each Gaussian is separable, so it is given as the 1D taps that,
// applied along x and then y, make it (the square root of its weight in each).
std::vector<Taps> spatialFilter(const ContrastSensitivity& csf, double pixelsPerDegree) {
    const float pi = std::numbers::pi_v<float>;
    const int radius = int(std::ceil(3.0 * std::sqrt(kLargestSensitivityScale / (2.0 * pi * pi)) * pixelsPerDegree));
    std::vector<Taps> terms;
    double sumOfSquares = 0;
    for (const auto& [a, b] : {std::pair(csf.a1, csf.b1), std::pair(csf.a2, csf.b2)}) {
        if (a == 0.0f) {
            continue;
        }
        Taps taps(std::size_t(2 * radius + 1));
        double sum = 0;
        for (int i = -radius; i <= radius; ++i) {
            const float x = float(i / pixelsPerDegree);
            taps[std::size_t(i + radius)] = std::sqrt(a * std::sqrt(pi / b)) * std::exp(-pi * pi * x * x / b);
            sum += taps[std::size_t(i + radius)];
        }
        sumOfSquares += sum * sum;  // the 2D term's sum
        terms.push_back(std::move(taps));
    }
    for (Taps& taps : terms) {
        for (float& tap : taps) {
            tap = float(tap / std::sqrt(sumOfSquares));
        }
    }
    return terms;
}

Plane filterChannel(const Plane& channel, const std::vector<Taps>& filter) {
    Plane sum(channel.width, channel.height);
    for (const Taps& taps : filter) {
        const Plane term = filterColumns(filterRows(channel, taps), taps);
        for (std::size_t i = 0; i < sum.values.size(); ++i) {
            sum.values[i] += term.values[i];
        }
    }
    return sum;
}

// An image as its three YCxCz planes.
std::array<Plane, 3> opponentPlanes(const Image& linear) {
    std::array<Plane, 3> planes{Plane(linear.width, linear.height), Plane(linear.width, linear.height),
                                Plane(linear.width, linear.height)};
    for (std::size_t i = 0; i < linear.pixels.size(); ++i) {
        const glm::vec3 ycxcz = linearRgbToYcxcz(glm::clamp(linear.pixels[i], 0.0f, 1.0f));
        for (int c = 0; c < 3; ++c) {
            planes[std::size_t(c)].values[i] = ycxcz[c];
        }
    }
    return planes;
}

// The image as the eye resolves it at this distance, back in linear RGB (clamped to [0, 1]) and
// then in Hunt-adjusted CIELab.
std::vector<glm::vec3> perceivedColours(const std::array<Plane, 3>& planes, double pixelsPerDegree) {
    std::array<Plane, 3> filtered{planes};
    for (std::size_t c = 0; c < 3; ++c) {
        filtered[c] = filterChannel(planes[c], spatialFilter(kSensitivity[c], pixelsPerDegree));
    }
    std::vector<glm::vec3> lab(planes[0].values.size());
    for (std::size_t i = 0; i < lab.size(); ++i) {
        const glm::vec3 ycxcz(filtered[0].values[i], filtered[1].values[i], filtered[2].values[i]);
        lab[i] = linearRgbToHuntLab(glm::clamp(ycxczToLinearRgb(ycxcz), 0.0f, 1.0f));
    }
    return lab;
}

// The colour pipeline's error: HyAB between the perceived colours, raised to qc and mapped onto
// [0, 1] so that the lower pc of the range takes the lower pt of the values.
float colourError(const glm::vec3& reference, const glm::vec3& test, float largest) {
    const float difference = std::pow(hyab(reference, test), kColourExponent);
    const float cut = kColourCut * largest;
    return difference < cut ? difference * kColourCutValue / cut
                            : kColourCutValue + (difference - cut) / (largest - cut) * (1.0f - kColourCutValue);
}

// The feature detectors along one axis: a Gaussian of standard deviation half the feature width,
// its first derivative (edges) and its second (points). The Gaussian sums to 1; each derivative's
// positive taps sum to 1 and its negative ones to -1.
struct FeatureTaps {
    Taps gaussian, edge, point;
};

void normaliseSigns(Taps& taps) {
    double positive = 0;
    double negative = 0;
    for (const float tap : taps) {
        (tap > 0 ? positive : negative) += std::abs(tap);
    }
    for (float& tap : taps) {
        tap = float(tap / (tap > 0 ? positive : negative));
    }
}

FeatureTaps featureTaps(double pixelsPerDegree) {
    const float sigma = float(0.5 * kFeatureWidthDegrees * pixelsPerDegree);
    const int radius = int(std::ceil(3.0f * sigma));
    FeatureTaps taps;
    double sum = 0;
    for (int i = -radius; i <= radius; ++i) {
        const float x = float(i);
        const float g = std::exp(-x * x / (2.0f * sigma * sigma));
        taps.gaussian.push_back(g);
        taps.edge.push_back(-x * g);
        taps.point.push_back((x * x / (sigma * sigma) - 1.0f) * g);
        sum += g;
    }
    for (float& tap : taps.gaussian) {
        tap = float(tap / sum);
    }
    normaliseSigns(taps.edge);
    normaliseSigns(taps.point);
    return taps;
}

// Edge and point strength (gradient magnitudes of the two detectors) of the achromatic channel,
// normalised to [0, 1].
struct Features {
    Plane edges, points;
};

Features detectFeatures(const Plane& luminanceYy, const FeatureTaps& taps) {
    Plane y(luminanceYy.width, luminanceYy.height);
    for (std::size_t i = 0; i < y.values.size(); ++i) {
        y.values[i] = (luminanceYy.values[i] + 16.0f) / 116.0f;
    }
    const Plane smoothRows = filterRows(y, taps.gaussian);
    const Plane dx = filterColumns(filterRows(y, taps.edge), taps.gaussian);
    const Plane ddx = filterColumns(filterRows(y, taps.point), taps.gaussian);
    const Plane dy = filterColumns(smoothRows, taps.edge);
    const Plane ddy = filterColumns(smoothRows, taps.point);
    Features features{Plane(y.width, y.height), Plane(y.width, y.height)};
    for (std::size_t i = 0; i < y.values.size(); ++i) {
        features.edges.values[i] = std::hypot(dx.values[i], dy.values[i]);
        features.points.values[i] = std::hypot(ddx.values[i], ddy.values[i]);
    }
    return features;
}

Image decodeSrgb(const Rgb8Image& encoded) {
    std::array<float, 256> linear{};
    for (std::size_t level = 0; level < linear.size(); ++level) {
        const double v = double(level) / 255.0;
        linear[level] = float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
    }
    Image image(encoded.width, encoded.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = {linear[encoded.bytes[3 * i]], linear[encoded.bytes[3 * i + 1]],
                           linear[encoded.bytes[3 * i + 2]]};
    }
    return image;
}

// The tone mapper HDR-FLIP views each exposure through: the papers' rational fit of ACES,
// (c0 x^2 + c1 x + c2) / (c3 x^2 + c4 x + c5), with the fit's 0.6 pre-exposure taken out.
constexpr std::array<double, 6> kAces = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

float toneMap(float x) {
    const float numerator = float(kAces[0]) * x * x + float(kAces[1]) * x + float(kAces[2]);
    return numerator / (float(kAces[3]) * x * x + float(kAces[4]) * x + float(kAces[5]));
}

// The input the tone mapper takes to `output`: the larger root of its quadratic.
double toneMapInverse(double output) {
    const double a = kAces[0] - output * kAces[3];
    const double b = kAces[1] - output * kAces[4];
    const double c = kAces[2] - output * kAces[5];
    if (a == 0.0) {
        return -c / b;
    }
    const double middle = -0.5 * b / a;
    return middle + std::sqrt(middle * middle - c / a);
}

float luminance(const glm::vec3& linear) {
    return 0.2126f * linear.r + 0.7152f * linear.g + 0.0722f * linear.b;
}

// A channel HDR-FLIP can expose: finite and non-negative, else 0.
glm::vec3 exposable(const glm::vec3& colour) {
    glm::vec3 result;
    for (int c = 0; c < 3; ++c) {
        result[c] = std::isfinite(colour[c]) && colour[c] > 0.0f ? colour[c] : 0.0f;
    }
    return result;
}

Image exposedAndToneMapped(const Image& linear, double exposure) {
    const float scale = float(std::exp2(exposure));
    Image out(linear.width, linear.height);
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
        const glm::vec3 colour = exposable(linear.pixels[i]) * scale;
        out.pixels[i] = {toneMap(colour.r), toneMap(colour.g), toneMap(colour.b)};
    }
    return out;
}

}  // namespace

double pixelsPerDegree(double distanceMetres, double widthPixels, double widthMetres) {
    return distanceMetres * (widthPixels / widthMetres) * (std::numbers::pi / 180.0);
}

double FlipMap::mean() const {
    double sum = 0;
    for (const float value : values) {
        sum += value;
    }
    return values.empty() ? 0.0 : sum / double(values.size());
}

double FlipMap::max() const {
    return values.empty() ? 0.0 : double(*std::max_element(values.begin(), values.end()));
}

FlipMap ldrFlip(const Image& reference, const Image& test, double pixelsPerDegree) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    const std::array<Plane, 3> referencePlanes = opponentPlanes(reference);
    const std::array<Plane, 3> testPlanes = opponentPlanes(test);
    const std::vector<glm::vec3> referenceLab = perceivedColours(referencePlanes, pixelsPerDegree);
    const std::vector<glm::vec3> testLab = perceivedColours(testPlanes, pixelsPerDegree);
    const FeatureTaps taps = featureTaps(pixelsPerDegree);
    const Features referenceFeatures = detectFeatures(referencePlanes[0], taps);
    const Features testFeatures = detectFeatures(testPlanes[0], taps);
    const float largest = largestColourDifference();
    FlipMap map{reference.width, reference.height, std::vector<float>(reference.pixels.size())};
    for (std::size_t i = 0; i < map.values.size(); ++i) {
        const float colour = colourError(referenceLab[i], testLab[i], largest);
        const float edge = std::abs(referenceFeatures.edges.values[i] - testFeatures.edges.values[i]);
        const float point = std::abs(referenceFeatures.points.values[i] - testFeatures.points.values[i]);
        const float feature = std::pow(std::max(edge, point) / std::numbers::sqrt2_v<float>, kFeatureExponent);
        // Features that differ push the error towards 1: colour^(1 - feature).
        map.values[i] = std::pow(colour, 1.0f - feature);
    }
    return map;
}

FlipMap ldrFlip(const Rgb8Image& reference, const Rgb8Image& test, double pixelsPerDegree) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    return ldrFlip(decodeSrgb(reference), decodeSrgb(test), pixelsPerDegree);
}

FlipExposures hdrFlipExposures(const Image& reference) {
    std::vector<float> luminances;
    luminances.reserve(reference.pixels.size());
    for (const glm::vec3& pixel : reference.pixels) {
        luminances.push_back(luminance(exposable(pixel)));
    }
    if (luminances.empty()) {
        return {};
    }
    const float brightest = *std::max_element(luminances.begin(), luminances.end());
    const auto median = luminances.begin() + std::ptrdiff_t(luminances.size() / 2);
    std::nth_element(luminances.begin(), median, luminances.end());
    // 85% of the tone mapper's white: the brightest pixel there at the first exposure, the
    // median one at the last. A black reference (or a black median) has no range to span.
    const double white = toneMapInverse(0.85);
    FlipExposures exposures;
    if (brightest > 0.0f) {
        exposures.start = std::log2(white / double(brightest));
        exposures.stop = *median > 0.0f ? std::log2(white / double(*median)) : exposures.start;
    }
    exposures.count = int(std::max(2.0, std::ceil(exposures.stop - exposures.start)));
    return exposures;
}

FlipMap hdrFlip(const Image& reference, const Image& test, double pixelsPerDegree, const FlipExposures& exposures) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    FlipMap map{reference.width, reference.height, std::vector<float>(reference.pixels.size(), 0.0f)};
    const int count = std::max(exposures.count, 2);
    for (int i = 0; i < count; ++i) {
        const double exposure = exposures.start + (exposures.stop - exposures.start) * i / (count - 1);
        const FlipMap atExposure =
            ldrFlip(exposedAndToneMapped(reference, exposure), exposedAndToneMapped(test, exposure), pixelsPerDegree);
        for (std::size_t p = 0; p < map.values.size(); ++p) {
            map.values[p] = std::max(map.values[p], atExposure.values[p]);
        }
    }
    return map;
}

FlipMap hdrFlip(const Image& reference, const Image& test, double pixelsPerDegree) {
    return hdrFlip(reference, test, pixelsPerDegree, hdrFlipExposures(reference));
}

Rgb8Image flipHeatMap(const FlipMap& map) {
    static constexpr std::array<glm::vec3, 5> kStops = {glm::vec3(0, 0, 0), glm::vec3(80, 18, 123),
                                                        glm::vec3(182, 54, 121), glm::vec3(251, 136, 97),
                                                        glm::vec3(252, 253, 191)};
    Rgb8Image heat{map.width, map.height, std::vector<std::uint8_t>(map.values.size() * 3)};
    for (std::size_t i = 0; i < map.values.size(); ++i) {
        const float position = std::clamp(map.values[i], 0.0f, 1.0f) * float(kStops.size() - 1);
        const std::size_t stop = std::min(std::size_t(position), kStops.size() - 2);
        const glm::vec3 colour = glm::mix(kStops[stop], kStops[stop + 1], position - float(stop));
        for (int c = 0; c < 3; ++c) {
            heat.bytes[3 * i + std::size_t(c)] = std::uint8_t(std::lround(colour[c]));
        }
    }
    return heat;
}

}  // namespace hexray::compare
