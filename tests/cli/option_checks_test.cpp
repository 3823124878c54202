// The command line's number checks: as strict as the scene file's.

#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "cli/option_checks.h"

namespace hexray::cli {
namespace {

TEST(IntegerProblem, AcceptsDecimalIntegersInTheRange) {
    EXPECT_EQ(integerProblem<std::int64_t>("1", 1, 16384), "");
    EXPECT_EQ(integerProblem<std::int64_t>("16384", 1, 16384), "");
    EXPECT_EQ(integerProblem<std::int64_t>("-7", -10, 10), "");
    EXPECT_EQ(integerProblem<std::uint64_t>("18446744073709551615", 0, std::numeric_limits<std::uint64_t>::max()), "");
}

TEST(IntegerProblem, RefusesEverythingElseEchoingTheText) {
    for (const char* text :
         {"0", "16385", "-1", "1e3", "0x10", " 12", "12 ", "+12", "1.5", "", "nan", "12abc", "99999999999999999999"}) {
        EXPECT_EQ(integerProblem<std::int64_t>(text, 1, 16384),
                  std::string("must be an integer between 1 and 16384 (got ") + text + ")")
            << text;
    }
    EXPECT_EQ(integerProblem<std::uint64_t>("-1", 0, std::numeric_limits<std::uint64_t>::max()),
              "must be an integer between 0 and 18446744073709551615 (got -1)");
    EXPECT_EQ(integerProblem<std::int64_t>("x", std::numeric_limits<std::int64_t>::min(),
                                           std::numeric_limits<std::int64_t>::max()),
              "must be an integer (got x)");
}

TEST(FiniteNumberProblem, AcceptsFiniteNumbersInTheRange) {
    for (const char* text : {"0", "100", "0.1", "1e-3", "2.5E1", "-0"}) {
        EXPECT_EQ(finiteNumberProblem(text, 0.0, 100.0), "") << text;
    }
    EXPECT_EQ(finiteNumberProblem("1e300", 0.0, std::numeric_limits<double>::max(), true), "");
}

TEST(FiniteNumberProblem, RefusesNonFiniteOutOfRangeAndMalformedText) {
    for (const char* text :
         {"nan", "NaN", "inf", "-inf", "infinity", "100.5", "-0.1", "1e999", "0x1p3", " 1", "", "1,5"}) {
        EXPECT_EQ(finiteNumberProblem(text, 0.0, 100.0),
                  std::string("must be a finite number between 0 and 100 (got ") + text + ")")
            << text;
    }
    EXPECT_EQ(finiteNumberProblem("0", 0.0, 1e308, true), "must be a finite number greater than 0 (got 0)");
    EXPECT_EQ(finiteNumberProblem("nan", 0.0, 1e308, true), "must be a finite number greater than 0 (got nan)");
}

}  // namespace
}  // namespace hexray::cli
