// A comparison accumulated band by band gives the same figures, bit for bit, as the whole images.

#include <gtest/gtest.h>

#include "compare/render_comparator.h"

namespace hexray {
namespace {

// A 5 x 4 image with a varied error against `reference`.
struct Pair {
    Image reference{5, 4};
    Image test{5, 4};
    std::vector<PixelClass> referenceClasses = std::vector<PixelClass>(20);
    std::vector<PixelClass> testClasses = std::vector<PixelClass>(20);
    Ambiguities ambiguity = Ambiguities(20);

    Pair() {
        for (std::size_t i = 0; i < 20; ++i) {
            reference.pixels[i] = glm::vec3(0.05f * float(i), 0.5f, 1.0f - 0.03f * float(i));
            test.pixels[i] = reference.pixels[i] + glm::vec3(i % 3 == 0 ? 0.01f * float(i) : 0.0f, 0.0f, -0.002f);
            referenceClasses[i] = PixelClass{std::uint32_t(i % 2), 0};
            testClasses[i] = PixelClass{std::uint32_t(i % 7 == 0 ? 1 - i % 2 : i % 2), i % 5 == 0 ? 2u : 0u};
            ambiguity[i] = i % 6 == 1   ? PixelAmbiguity{true, 0, false}
                           : i % 4 == 3 ? PixelAmbiguity{false, 2, false}
                                        : PixelAmbiguity{};
        }
    }
};

// Rows [first, first + rows) of `values` (row length 5).
template <class T>
T rowsOf(const T& values, std::size_t first, std::size_t rows) {
    return T(values.begin() + std::ptrdiff_t(5 * first), values.begin() + std::ptrdiff_t(5 * (first + rows)));
}

Image rowsOf(const Image& image, std::uint32_t first, std::uint32_t rows) {
    Image band(5, rows);
    band.pixels = rowsOf(image.pixels, first, rows);
    return band;
}

TEST(RenderComparator, BandsGiveTheWholeImagesFigures) {
    const Pair pair;
    const RenderComparison whole = compareRenders(pair.reference, pair.referenceClasses, pair.ambiguity, pair.test,
                                                  pair.testClasses, Encoding::Srgb);
    RenderComparator comparator;
    for (std::uint32_t first = 0; first < 4; first += 3) {
        const std::uint32_t rows = std::min(3u, 4u - first);
        const Image reference = rowsOf(pair.reference, first, rows);
        const Image test = rowsOf(pair.test, first, rows);
        const std::vector<PixelClass> referenceClasses = rowsOf(pair.referenceClasses, first, rows);
        const std::vector<PixelClass> testClasses = rowsOf(pair.testClasses, first, rows);
        const Rgb8Image reference8 = encodeImage(reference, Encoding::Srgb);
        const Rgb8Image test8 = encodeImage(test, Encoding::Srgb);
        comparator.add({reference, referenceClasses, reference8}, {test, testClasses, test8},
                       rowsOf(pair.ambiguity, first, rows));
    }
    const RenderComparison banded = comparator.result();
    ASSERT_GT(whole.topology.mismatches, 0u);
    ASSERT_GT(whole.topology.ambiguous, 0u);
    ASSERT_GT(whole.linear.maxAbs, 0.0);
    EXPECT_EQ(banded.topology.pixels, 20u);
    EXPECT_EQ(banded.topology.ambiguous, whole.topology.ambiguous);
    EXPECT_EQ(banded.topology.excused, whole.topology.excused);
    EXPECT_EQ(banded.topology.mismatches, whole.topology.mismatches);
    EXPECT_EQ(banded.topology.nodeMismatches, whole.topology.nodeMismatches);
    EXPECT_EQ(banded.topology.lightMismatches, whole.topology.lightMismatches);
    for (const auto& [b, w] : {std::pair(banded.linear, whole.linear), std::pair(banded.encoded, whole.encoded)}) {
        EXPECT_EQ(b.pixels, w.pixels);
        EXPECT_EQ(b.maxAbs, w.maxAbs);
        EXPECT_EQ(b.meanAbs, w.meanAbs);
        EXPECT_EQ(b.rmse, w.rmse);
        EXPECT_EQ(b.pixelsOverOneLevel, w.pixelsOverOneLevel);
    }
}

TEST(RenderComparator, BandsOfDifferentSizesAreRefused) {
    const Pair pair;
    const Image shorter = rowsOf(pair.test, 0, 3);
    const Rgb8Image reference8 = encodeImage(pair.reference, Encoding::Srgb);
    const Rgb8Image shorter8 = encodeImage(shorter, Encoding::Srgb);
    RenderComparator comparator;
    EXPECT_THROW(comparator.add({pair.reference, pair.referenceClasses, reference8},
                                {shorter, rowsOf(pair.testClasses, 0, 3), shorter8}, {}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace hexray
