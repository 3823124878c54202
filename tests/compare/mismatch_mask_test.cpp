// compare --mask: one colour per kind of disagreement, in the documented order of precedence.

#include <gtest/gtest.h>

#include "compare/compare.h"

namespace hexray {
namespace {

TEST(MismatchMask, EachKindOfDisagreementHasItsColour) {
    // Pixels: agreement, one level off (still agreement), colour off, topology off, ambiguous.
    const Rgb8Image reference{5, 1, {10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10}};
    const Rgb8Image test{5, 1, {10, 10, 10, 11, 10, 9, 10, 13, 10, 10, 10, 10, 90, 10, 10}};
    const std::vector<PixelClass> referenceClasses(5, PixelClass{0, 2});
    std::vector<PixelClass> testClasses = referenceClasses;
    testClasses[3].flags = 0;  // a light lost
    testClasses[4].node = 1;   // ambiguous wins over the class and colour differences
    const PixelMask ambiguous = {false, false, false, false, true};
    const Rgb8Image mask = mismatchMask(referenceClasses, testClasses, ambiguous, reference, test);
    EXPECT_EQ(mask.bytes, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 255, 255, 0, 255, 0, 0, 0, 64, 255}));
}

TEST(MismatchMask, SizesMustMatch) {
    const Rgb8Image image{2, 1, std::vector<std::uint8_t>(6, 0)};
    EXPECT_THROW(mismatchMask(std::vector<PixelClass>(1), std::vector<PixelClass>(2), {}, image, image),
                 std::invalid_argument);
}

}  // namespace
}  // namespace hexray
