// FLIP (compare/flip.h): its properties, and its values on synthesised image pairs, cross-checked
// against NVlabs' reference implementation (FLIP.h of github.com/NVlabs/flip, run on the same
// pairs written out as PNG and OpenEXR files; docs/diff.md).

#include "compare/flip.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

namespace hexray {
namespace {

constexpr std::uint32_t kSize = 64;

// A reference with gradients, edges and a dot (every feature FLIP looks for).
Rgb8Image syntheticReference() {
    Rgb8Image image{kSize, kSize, std::vector<std::uint8_t>(kSize * kSize * 3)};
    for (std::uint32_t y = 0; y < kSize; ++y) {
        for (std::uint32_t x = 0; x < kSize; ++x) {
            std::uint8_t* pixel = &image.bytes[3 * (y * kSize + x)];
            pixel[0] = std::uint8_t((x * 4) & 255);
            pixel[1] = std::uint8_t((y * 4) & 255);
            pixel[2] = ((x / 8 + y / 8) % 2) ? 200 : 40;
        }
    }
    image.bytes[3 * (32 * kSize + 8) + 1] = 255;
    return image;
}

// The reference with a brighter square, red and green swapped in a corner and the dot gone.
Rgb8Image syntheticTest() {
    Rgb8Image image = syntheticReference();
    for (std::uint32_t y = 0; y < kSize; ++y) {
        for (std::uint32_t x = 0; x < kSize; ++x) {
            std::uint8_t* pixel = &image.bytes[3 * (y * kSize + x)];
            if (x >= 16 && x < 48 && y >= 16 && y < 48) {
                for (int c = 0; c < 3; ++c) {
                    pixel[c] = std::uint8_t(std::min(255, pixel[c] + 40));
                }
            } else if (x < 16 && y >= 48) {
                std::swap(pixel[0], pixel[1]);
            }
        }
    }
    image.bytes[3 * (32 * kSize + 8) + 1] = std::uint8_t(32 * 4);  // the dot's row's green
    return image;
}

// Linear HDR versions: values up to 16.
Image hdrFrom(const Rgb8Image& encoded) {
    Image image(encoded.width, encoded.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float v = float(encoded.bytes[3 * i + std::size_t(c)]) / 255.0f;
            image.pixels[i][c] = v * v * 16.0f;
        }
    }
    return image;
}

TEST(Flip, DefaultViewingConditionIsThePapers) {
    EXPECT_NEAR(kDefaultPixelsPerDegree, 67.0206, 1e-4);
}

TEST(Flip, IdenticalImagesAreZeroEverywhere) {
    const Rgb8Image image = syntheticReference();
    const FlipMap ldr = ldrFlip(image, image, kDefaultPixelsPerDegree);
    EXPECT_EQ(ldr.mean(), 0.0);
    EXPECT_EQ(ldr.max(), 0.0);
    const FlipMap hdr = hdrFlip(hdrFrom(image), hdrFrom(image), kDefaultPixelsPerDegree);
    EXPECT_EQ(hdr.max(), 0.0);
}

TEST(Flip, ValuesAreInTheUnitInterval) {
    const FlipMap map = ldrFlip(syntheticReference(), syntheticTest(), kDefaultPixelsPerDegree);
    ASSERT_EQ(map.values.size(), std::size_t(kSize) * kSize);
    for (const float value : map.values) {
        ASSERT_GE(value, 0.0f);
        ASSERT_LE(value, 1.0f);
    }
    EXPECT_GT(map.max(), 0.5);  // swapped red and green is plain to see
}

TEST(Flip, BlackAgainstWhiteIsNearlyTheLargestError) {
    const Rgb8Image black{8, 8, std::vector<std::uint8_t>(8 * 8 * 3, 0)};
    const Rgb8Image white{8, 8, std::vector<std::uint8_t>(8 * 8 * 3, 255)};
    const FlipMap map = ldrFlip(black, white, kDefaultPixelsPerDegree);
    // Flat images have no features: the colour error alone, HyAB(black, white) = 100 on the
    // remapped scale, above the cut (0.95) and below green against blue (1).
    EXPECT_GT(map.mean(), 0.95);
    EXPECT_LT(map.mean(), 1.0);
    EXPECT_FLOAT_EQ(*std::min_element(map.values.begin(), map.values.end()), float(map.max()));
}

// LDR-FLIP treats its two images alike (HyAB and the feature differences are symmetric);
// HDR-FLIP does not, since the reference alone chooses the exposures.
TEST(Flip, LdrFlipIsSymmetric) {
    const FlipMap forward = ldrFlip(syntheticReference(), syntheticTest(), kDefaultPixelsPerDegree);
    const FlipMap backward = ldrFlip(syntheticTest(), syntheticReference(), kDefaultPixelsPerDegree);
    for (std::size_t i = 0; i < forward.values.size(); ++i) {
        ASSERT_NEAR(forward.values[i], backward.values[i], 1e-5f) << "pixel " << i;
    }
}

TEST(Flip, HdrExposuresComeFromTheReference) {
    const FlipExposures exposures = hdrFlipExposures(hdrFrom(syntheticReference()));
    EXPECT_LT(exposures.start, exposures.stop);
    EXPECT_EQ(exposures.count, int(std::max(2.0, std::ceil(exposures.stop - exposures.start))));
    const Image black(4, 4);
    EXPECT_EQ(hdrFlipExposures(black).start, 0.0);
    EXPECT_EQ(hdrFlipExposures(black).count, 2);
}

// The values NVlabs' FLIP.h gives for the same pairs (written as an 8-bit PNG and a 32-bit float
// OpenEXR, read back and passed to FLIP::evaluate at its default 67.02 pixels per degree): LDR mean
// 0.230351, max 0.989251; HDR mean 0.243214, max 0.990430, exposures -2.7773 to -1.0638 in 2.
// Per pixel, this implementation is within 4e-5 of it.
TEST(Flip, AgreesWithTheReferenceImplementationOnASynthesisedPair) {
    const FlipMap ldr = ldrFlip(syntheticReference(), syntheticTest(), kDefaultPixelsPerDegree);
    EXPECT_NEAR(ldr.mean(), 0.230351, 1e-5);
    EXPECT_NEAR(ldr.max(), 0.989251, 1e-4);
    const Image hdrReference = hdrFrom(syntheticReference());
    const FlipExposures exposures = hdrFlipExposures(hdrReference);
    EXPECT_NEAR(exposures.start, -2.7773, 1e-4);
    EXPECT_NEAR(exposures.stop, -1.0638, 1e-4);
    EXPECT_EQ(exposures.count, 2);
    const FlipMap hdr = hdrFlip(hdrReference, hdrFrom(syntheticTest()), kDefaultPixelsPerDegree);
    EXPECT_NEAR(hdr.mean(), 0.243214, 1e-5);
    EXPECT_NEAR(hdr.max(), 0.990430, 1e-4);
}

TEST(Flip, HeatMapIsBlackWhereThereIsNoDifference) {
    const FlipMap map{3, 1, {0.0f, 0.5f, 1.0f}};
    const Rgb8Image heat = flipHeatMap(map);
    ASSERT_EQ(heat.bytes.size(), 9u);
    EXPECT_EQ(heat.bytes[0] + heat.bytes[1] + heat.bytes[2], 0);
    EXPECT_GT(heat.bytes[3], 0);
    EXPECT_GT(heat.bytes[6] + heat.bytes[7] + heat.bytes[8], heat.bytes[3] + heat.bytes[4] + heat.bytes[5]);
}

TEST(Flip, ImagesOfDifferentSizesAreRefused) {
    const Rgb8Image small{2, 2, std::vector<std::uint8_t>(12, 0)};
    EXPECT_THROW(ldrFlip(small, syntheticReference(), kDefaultPixelsPerDegree), std::invalid_argument);
}

}  // namespace
}  // namespace hexray
