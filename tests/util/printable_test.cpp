// Quoted text with its control characters escaped, and nothing else changed.

#include <string>

#include <gtest/gtest.h>

#include "util/printable.h"

namespace hexray {
namespace {

TEST(Printable, KeepsPrintableTextOfAnyLanguage) {
    EXPECT_EQ(printable("scenes/lecture demo.json"), "scenes/lecture demo.json");
    EXPECT_EQ(printable("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8C\x88 \\x1b"),
              "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8C\x88 \\x1b");
    EXPECT_EQ(printable(""), "");
}

TEST(Printable, EscapesC0ControlsAndDelAsBytes) {
    EXPECT_EQ(printable("a\x1b[31mred"), "a\\x1b[31mred");
    EXPECT_EQ(printable(std::string("\0\t\n\r\x07\x7f", 6)), "\\x00\\x09\\x0a\\x0d\\x07\\x7f");
}

TEST(Printable, EscapesC1ControlsAsCodePoints) {
    EXPECT_EQ(printable("\xC2\x80\xC2\x9B"
                        "2J\xC2\x9F\xC2\xA0"),
              "\\u0080\\u009b2J\\u009f\xC2\xA0");  // U+00A0 is printable
}

TEST(Printable, EscapesEveryByteThatIsNotValidUtf8) {
    EXPECT_EQ(printable("\x9b"
                        "2J"),
              "\\x9b2J");                                              // a lone continuation byte (CSI in Latin-1)
    EXPECT_EQ(printable("\xC3"), "\\xc3");                             // a sequence cut short
    EXPECT_EQ(printable("\xC0\xAF"), "\\xc0\\xaf");                    // an overlong '/'
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xed\\xa0\\x80");           // a surrogate
    EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // above U+10FFFF
    EXPECT_EQ(printable("\xFF\xFE"), "\\xff\\xfe");
}

TEST(Printable, ItsOutputIsItsOwnPrintableForm) {
    const std::string once = printable("x\x1b]0;t\x07\xC2\x9B\x9B\xC3\xA9");
    EXPECT_EQ(printable(once), once);
}

}  // namespace
}  // namespace hexray
