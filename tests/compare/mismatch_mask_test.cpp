// compare --mask: one colour per kind of disagreement, in the documented order of precedence.

#include <limits>

#include <gtest/gtest.h>

#include "compare/compare.h"

namespace hexray {
namespace {

TEST(MismatchMask, EachKindOfDisagreementHasItsColour) {
    // Pixels: agreement, one level off (still agreement), colour off, a light lost, an excused
    // node, a near-tied light both renders lit (with its colour off), and a near-tied checker
    // cell beside a lost light that was not near-tied.
    const Rgb8Image reference{7, 1, std::vector<std::uint8_t>(21, 10)};
    const Rgb8Image test{7, 1, {10, 10, 10, 11, 10, 9, 10, 13, 10, 10, 10, 10, 90, 10, 10, 10, 30, 10, 10, 10, 10}};
    const std::vector<PixelClass> referenceClasses(7, PixelClass{0, 2});
    std::vector<PixelClass> testClasses = referenceClasses;
    testClasses[3].flags = 0;
    testClasses[4].node = 1;
    testClasses[6].flags = PixelClass::kOddCheckerBit;
    Ambiguities ambiguity(7);
    ambiguity[4].node = true;
    ambiguity[5].flags = PixelClass::litBit(0);
    ambiguity[6].flags = PixelClass::kOddCheckerBit;
    const Rgb8Image mask = mismatchMask(referenceClasses, testClasses, ambiguity, reference, test);
    EXPECT_EQ(mask.bytes, (std::vector<std::uint8_t>{0, 0, 0,  0,   0,   0,   255, 255, 0, 255, 0,
                                                     0, 0, 64, 255, 255, 255, 0,   255, 0, 0}));
}

TEST(MismatchMask, NearTiedAndAgreeingIsNavy) {
    const Rgb8Image image{1, 1, {10, 10, 10}};
    const std::vector<PixelClass> classes(1, PixelClass{0, 0});
    const Ambiguities nearTiedLight = {PixelAmbiguity{false, PixelClass::litBit(0), false}};
    const Rgb8Image mask = mismatchMask(classes, classes, nearTiedLight, image, image);
    EXPECT_EQ(mask.bytes, (std::vector<std::uint8_t>(mask_colour::kNearTied, mask_colour::kNearTied + 3)));
}

TEST(MismatchMask, AColourThatIsNotFiniteAndNonNegativeIsMagentaWhateverElse) {
    const Rgb8Image image{3, 1, std::vector<std::uint8_t>(9, 10)};
    const std::vector<PixelClass> classes(3, PixelClass{0, 0});
    Image reference(3, 1);
    Image test(3, 1);
    test.pixels[0].r = std::numeric_limits<float>::quiet_NaN();
    reference.pixels[1].g = -1.0f;
    const Ambiguities everything(3, PixelAmbiguity::everything());
    const Rgb8Image mask = mismatchMask(classes, classes, everything, image, image, &reference, &test);
    EXPECT_EQ(mask.bytes, (std::vector<std::uint8_t>{255, 0, 255, 255, 0, 255, 0, 64, 255}));
}

TEST(MismatchMask, SizesMustMatch) {
    const Rgb8Image image{2, 1, std::vector<std::uint8_t>(6, 0)};
    EXPECT_THROW(mismatchMask(std::vector<PixelClass>(1), std::vector<PixelClass>(2), {}, image, image),
                 std::invalid_argument);
}

}  // namespace
}  // namespace hexray
