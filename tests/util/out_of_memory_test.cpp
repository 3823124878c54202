// Running out of memory inside a step that holds the scene is reported as the scene's size.

#include <new>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "util/out_of_memory.h"

namespace hexray {
namespace {

TEST(OutOfMemory, InsideAStepSaysWhatTheStepHeld) {
    try {
        holding([] { return std::string("the scene's 3 spheres"); }, []() -> int { throw std::bad_alloc(); });
        FAIL() << "no exception";
    } catch (const OutOfMemory& error) {
        EXPECT_EQ(std::string(error.what()), "the scene's 3 spheres");
    }
}

TEST(OutOfMemory, AnInnerStepsWordsStand) {
    try {
        const auto inner = []() -> int {
            return holding([] { return std::string("inner"); }, []() -> int { throw std::bad_alloc(); });
        };
        holding([] { return std::string("outer"); }, inner);
        FAIL() << "no exception";
    } catch (const OutOfMemory& error) {
        EXPECT_EQ(std::string(error.what()), "inner");
    }
}

TEST(OutOfMemory, OtherFailuresAndResultsPassThrough) {
    EXPECT_EQ(holding([] { return std::string("unused"); }, [] { return 42; }), 42);
    EXPECT_THROW(holding([] { return std::string("unused"); }, []() -> int { throw std::runtime_error("x"); }),
                 std::runtime_error);
}

}  // namespace
}  // namespace hexray
