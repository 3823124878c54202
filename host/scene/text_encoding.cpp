#include "scene/text_encoding.h"

namespace hexray::inline scene {
namespace {

struct WideEncoding {
    const char* name;       // for the message
    const char* iconvName;  // for the command that converts it
};

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

std::optional<WideEncoding> wideEncoding(std::string_view text) {
    using namespace std::string_view_literals;
    constexpr WideEncoding kUtf32Le{"UTF-32 (little-endian)", "UTF-32LE"};
    constexpr WideEncoding kUtf32Be{"UTF-32 (big-endian)", "UTF-32BE"};
    constexpr WideEncoding kUtf16Le{"UTF-16 (little-endian)", "UTF-16LE"};
    constexpr WideEncoding kUtf16Be{"UTF-16 (big-endian)", "UTF-16BE"};
    // Byte order marks, UTF-32's first: FF FE 00 00 also begins like UTF-16's.
    if (startsWith(text, "\xFF\xFE\0\0"sv))
        return kUtf32Le;
    if (startsWith(text, "\0\0\xFE\xFF"sv))
        return kUtf32Be;
    if (startsWith(text, "\xFF\xFE"sv))
        return kUtf16Le;
    if (startsWith(text, "\xFE\xFF"sv))
        return kUtf16Be;
    // An ASCII first character, with the NUL bytes a wider encoding gives it.
    const auto isNul = [&](std::size_t i) { return text[i] == '\0'; };
    if (text.size() >= 4 && isNul(0) && isNul(1) && isNul(2) && !isNul(3))
        return kUtf32Be;
    if (text.size() >= 4 && !isNul(0) && isNul(1) && isNul(2) && isNul(3))
        return kUtf32Le;
    if (text.size() >= 2 && isNul(0) && !isNul(1))
        return kUtf16Be;
    if (text.size() >= 2 && !isNul(0) && isNul(1))
        return kUtf16Le;
    return std::nullopt;
}

}  // namespace

std::optional<std::string> wideEncodingProblem(std::string_view text) {
    const std::optional<WideEncoding> encoding = wideEncoding(text);
    if (!encoding) {
        return std::nullopt;
    }
    return std::string("the file is ") + encoding->name + " text, and scene files are UTF-8: convert it, e.g. with " +
           "iconv -f " + encoding->iconvName + " -t UTF-8";
}

}  // namespace hexray::scene
