#pragma once
// printf into a std::string, for report lines: the whole text, however long.

#include <cstdio>
#include <string>

namespace hexray::inline util {

template <typename... Values>
std::string formatted(const char* pattern, Values... values) {
    const int length = std::snprintf(nullptr, 0, pattern, values...);
    if (length <= 0) {
        return {};
    }
    std::string text(std::size_t(length) + 1, '\0');
    std::snprintf(text.data(), text.size(), pattern, values...);
    text.pop_back();
    return text;
}

}  // namespace hexray::util
