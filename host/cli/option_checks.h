#pragma once
// Checks for the command line's values, as strict as the scene file's: a count is a decimal
// integer within its range (no sign '+', spaces, hex or exponent), a number is finite (no nan or
// inf), a path is not empty. Each message names the range and echoes the text given; CLI11 puts
// the option's name in front.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <CLI/CLI.hpp>

#include "strip/strip.h"

namespace hexray::cli {

// "" when `text` is a decimal integer in [min, max]; else why not. Instantiated for
// std::int64_t and std::uint64_t.
template <class Integer>
std::string integerProblem(const std::string& text, Integer min, Integer max);

// "" when `text` is a finite number in [min, max] (above `min`, not at it, with `minExcluded`);
// else why not.
std::string finiteNumberProblem(const std::string& text, double min, double max, bool minExcluded = false);

template <class Integer>
CLI::Validator IntegerBetween(Integer min, Integer max) {
    using Wide = std::conditional_t<std::is_signed_v<Integer>, std::int64_t, std::uint64_t>;
    return CLI::Validator([=](std::string& text) { return integerProblem<Wide>(text, min, max); },
                          "in " + std::to_string(min) + ".." + std::to_string(max));
}

// Any integer of a signed type: only the syntax is checked (the command checks the range itself).
template <class Integer>
CLI::Validator AnInteger() {
    return IntegerBetween<Integer>(std::numeric_limits<Integer>::min(), std::numeric_limits<Integer>::max());
}

CLI::Validator FiniteNumberBetween(double min, double max);
CLI::Validator FiniteNumberAbove(double min);  // and below the largest double
CLI::Validator NotEmpty();
// An --aov directory: not "-", since an AOV set is several files.
CLI::Validator AovDirectoryName();

// "I/N": strip I of N, 0 <= I < N <= kMaxStrips; "" when `text` is one, else why not.
std::string stripProblem(const std::string& text);
CLI::Validator StripSpec();
// The strip `text` names (checked by StripSpec); nullopt for "".
std::optional<Strip> parseStrip(const std::string& text);

}  // namespace hexray::cli
