#include "cli/option_checks.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

namespace hexray::cli {
namespace {

std::string numberText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

template <class Number>
bool parsesWhole(const std::string& text, Number& value) {
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && stop == end;
}

}  // namespace

template <class Integer>
std::string integerProblem(const std::string& text, Integer min, Integer max) {
    // from_chars reads an optional '-' (for signed types) and decimal digits only.
    Integer value = 0;
    if (parsesWhole(text, value) && value >= min && value <= max) {
        return "";
    }
    if (std::is_signed_v<Integer> && min == std::numeric_limits<Integer>::min() &&
        max == std::numeric_limits<Integer>::max()) {
        return "must be an integer (got " + text + ")";
    }
    return "must be an integer between " + std::to_string(min) + " and " + std::to_string(max) + " (got " + text + ")";
}

template std::string integerProblem<std::int64_t>(const std::string&, std::int64_t, std::int64_t);
template std::string integerProblem<std::uint64_t>(const std::string&, std::uint64_t, std::uint64_t);

std::string finiteNumberProblem(const std::string& text, double min, double max, bool minExcluded) {
    double value = 0;
    const bool finite = parsesWhole(text, value) && std::isfinite(value);
    if (finite && (minExcluded ? value > min : value >= min) && value <= max) {
        return "";
    }
    if (minExcluded) {
        return "must be a finite number greater than " + numberText(min) + " (got " + text + ")";
    }
    return "must be a finite number between " + numberText(min) + " and " + numberText(max) + " (got " + text + ")";
}

CLI::Validator FiniteNumberBetween(double min, double max) {
    return CLI::Validator([=](std::string& text) { return finiteNumberProblem(text, min, max); },
                          "in [" + numberText(min) + ", " + numberText(max) + "]");
}

CLI::Validator FiniteNumberAbove(double min) {
    return CLI::Validator(
        [=](std::string& text) { return finiteNumberProblem(text, min, std::numeric_limits<double>::max(), true); },
        "> " + numberText(min));
}

CLI::Validator NotEmpty() {
    return CLI::Validator([](std::string& text) { return text.empty() ? std::string("must not be empty") : ""; }, "");
}

CLI::Validator AovDirectoryName() {
    return CLI::Validator(
        [](std::string& text) {
            return text != "-" ? std::string()
                               : "an AOV set is several files (depth, normal, object id and each light's, with PNG "
                                 "previews), which standard output cannot hold: name a directory";
        },
        "");
}

std::string stripProblem(const std::string& text) {
    const std::size_t slash = text.find('/');
    std::uint64_t index = 0;
    std::uint64_t count = 0;
    const bool valid = slash != std::string::npos && parsesWhole(text.substr(0, slash), index) &&
                       parsesWhole(text.substr(slash + 1), count) && count >= 1 && count <= kMaxStrips && index < count;
    return valid
               ? ""
               : "must be I/N, strip I of N, with 0 <= I < N <= " + std::to_string(kMaxStrips) + " (got " + text + ")";
}

CLI::Validator StripSpec() {
    return CLI::Validator([](std::string& text) { return stripProblem(text); }, "I/N");
}

std::optional<Strip> parseStrip(const std::string& text) {
    if (text.empty() || !stripProblem(text).empty()) {
        return std::nullopt;
    }
    const std::size_t slash = text.find('/');
    return Strip{std::uint32_t(std::stoul(text.substr(0, slash))), std::uint32_t(std::stoul(text.substr(slash + 1)))};
}

}  // namespace hexray::cli
