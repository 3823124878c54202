// What a comparison holds against one pixel: a difference in a near-tied decision is excused,
// every other decision of the same pixel must still agree, and the colour is compared where the
// classes leave no honest room for it to differ.

#include <limits>

#include <gtest/gtest.h>

#include "compare/compare.h"

namespace hexray {
namespace {

using Mismatch = PixelJudgement::Mismatch;

constexpr std::uint32_t kChecker = PixelClass::kOddCheckerBit;
constexpr std::uint32_t kLight0 = PixelClass::litBit(0);
constexpr std::uint32_t kLight1 = PixelClass::litBit(1);
constexpr std::uint32_t kLight2 = PixelClass::litBit(2);
constexpr std::uint32_t kLight3 = PixelClass::litBit(3);

TEST(JudgePixel, NearTiedOnACheckerEdgeStillMustAgreeOnTheNodeAndTheLitLights) {
    const PixelClass reference{3, kChecker | kLight0};
    const PixelAmbiguity checkerEdge{false, kChecker, false};
    const PixelJudgement otherCell = judgePixel(reference, {3, kLight0}, checkerEdge);
    EXPECT_EQ(otherCell.mismatch, Mismatch::None);
    EXPECT_TRUE(otherCell.excused);
    EXPECT_FALSE(otherCell.colourCompared);
    EXPECT_EQ(judgePixel(reference, {2, kChecker | kLight0}, checkerEdge).mismatch, Mismatch::Node);
    EXPECT_EQ(judgePixel(reference, {3, kChecker}, checkerEdge).mismatch, Mismatch::Lights);
    EXPECT_EQ(judgePixel(reference, {3, kLight0 | kLight1}, checkerEdge).mismatch, Mismatch::Lights);
}

TEST(JudgePixel, NearTiedOnAShadowEdgeOfLightTwoStillMustAgreeOnTheRest) {
    const PixelClass reference{0, kLight0 | kLight2 | kLight3};
    const PixelAmbiguity shadowEdge{false, kLight2, false};
    EXPECT_EQ(judgePixel(reference, {0, kLight0 | kLight3}, shadowEdge).mismatch, Mismatch::None);
    EXPECT_EQ(judgePixel(reference, {1, kLight0 | kLight2 | kLight3}, shadowEdge).mismatch, Mismatch::Node);
    EXPECT_EQ(judgePixel(reference, {0, kChecker | kLight0 | kLight2 | kLight3}, shadowEdge).mismatch,
              Mismatch::Checker);
    for (const std::uint32_t lost : {kLight0, kLight3}) {
        EXPECT_EQ(judgePixel(reference, {0, (kLight0 | kLight2 | kLight3) & ~lost}, shadowEdge).mismatch,
                  Mismatch::Lights);
    }
    EXPECT_EQ(judgePixel(reference, {0, kLight0 | kLight1 | kLight2 | kLight3}, shadowEdge).mismatch, Mismatch::Lights);
}

TEST(JudgePixel, TheColourIsComparedWhenTheNearTiedDecisionWentTheSameWay) {
    const PixelClass reference{0, kLight0 | kLight2};
    const PixelJudgement same = judgePixel(reference, reference, {false, kLight2, false});
    EXPECT_TRUE(same.ambiguous);
    EXPECT_FALSE(same.excused);
    EXPECT_TRUE(same.colourCompared);
    // Not when something outside the class was near-tied (another sample, a light beyond 30).
    const PixelJudgement other = judgePixel(reference, reference, {false, 0, true});
    EXPECT_TRUE(other.excused);
    EXPECT_FALSE(other.colourCompared);
}

TEST(JudgePixel, ANearTiedNodeThatDiffersExcusesTheWholePixel) {
    const PixelJudgement judgement = judgePixel({0, kLight0}, {PixelClass::kBackground, 0}, {true, 0, false});
    EXPECT_EQ(judgement.mismatch, Mismatch::None);
    EXPECT_TRUE(judgement.excused);
    EXPECT_FALSE(judgement.colourCompared);
    // The same node with a near-tied node decision (which node is nearer): the rest still counts,
    // but not the colour, as the hit may be as ill-conditioned as the decision.
    const PixelJudgement sameNode = judgePixel({0, kLight0}, {0, 0}, {true, 0, false});
    EXPECT_EQ(sameNode.mismatch, Mismatch::Lights);
    EXPECT_FALSE(sameNode.colourCompared);
    EXPECT_TRUE(judgePixel({0, kLight0}, {0, kLight0}, {true, 0, false}).excused);
}

TEST(JudgePixel, AnUnambiguousPixelIsComparedWhole) {
    const PixelJudgement agreeing = judgePixel({1, kLight1}, {1, kLight1}, {});
    EXPECT_FALSE(agreeing.ambiguous);
    EXPECT_TRUE(agreeing.colourCompared);
    const PixelJudgement lost = judgePixel({1, kLight1}, {1, 0}, {});
    EXPECT_EQ(lost.mismatch, Mismatch::Lights);
    EXPECT_FALSE(lost.excused);
    EXPECT_TRUE(lost.colourCompared);
}

TEST(CompareTopology, CountsAmbiguousExcusedAndMismatchedPixels) {
    const std::vector<PixelClass> reference(4, PixelClass{0, kChecker | kLight0});
    const std::vector<PixelClass> test = {{0, kChecker | kLight0}, {0, kLight0}, {0, kLight0}, {0, kChecker}};
    const Ambiguities ambiguity = {{false, kChecker, false}, {false, kChecker, false}, {}, {false, kChecker, false}};
    const TopologyComparison topology = compareTopology(reference, test, ambiguity);
    EXPECT_EQ(topology.pixels, 4u);
    EXPECT_EQ(topology.ambiguous, 3u);
    EXPECT_EQ(topology.excused, 1u);
    EXPECT_EQ(topology.mismatches, 2u);
    EXPECT_EQ(topology.checkerMismatches, 1u);
    EXPECT_EQ(topology.lightMismatches, 1u);
    EXPECT_DOUBLE_EQ(topology.ambiguousShare(), 0.75);
}

TEST(CompareTopology, AWholePixelMaskExcusesEverything) {
    const std::vector<PixelClass> reference(2, PixelClass{0, kLight0});
    const std::vector<PixelClass> test = {{1, 0}, {1, 0}};
    const TopologyComparison topology = compareTopology(reference, test, PixelMask{true, false});
    EXPECT_EQ(topology.ambiguous, 1u);
    EXPECT_EQ(topology.excused, 1u);
    EXPECT_EQ(topology.nodeMismatches, 1u);
}

TEST(RenderComparator, CountsInvalidColoursOnEveryPixel) {
    // Both pixels excused whole, and still: a NaN in the test, a negative channel in the reference.
    Image reference(3, 1);
    Image test(3, 1);
    test.pixels[0].b = std::numeric_limits<float>::infinity();
    reference.pixels[2].r = -0.5f;
    const std::vector<PixelClass> classes(3);
    const RenderComparison comparison =
        compareRenders(reference, classes, PixelMask{true, false, true}, test, classes, Encoding::Linear);
    EXPECT_EQ(comparison.invalidColours, 2u);
    EXPECT_FALSE(judge(comparison, Tolerance{}).valuesOk);
    EXPECT_FALSE(judge(comparison, Tolerance{}).passed());
}

TEST(Judge, FailsWhenTooManyPixelsAreAmbiguous) {
    RenderComparison comparison;
    comparison.topology.pixels = 100;
    comparison.topology.ambiguous = 6;
    EXPECT_FALSE(judge(comparison, Tolerance{}).passed());
    EXPECT_FALSE(judge(comparison, Tolerance{}).ambiguousOk);
    Tolerance raised;
    raised.maxAmbiguousPercent = 6.0;
    EXPECT_TRUE(judge(comparison, raised).passed());
    EXPECT_TRUE(judge(comparison, raised).valuesOk);
}

}  // namespace
}  // namespace hexray
