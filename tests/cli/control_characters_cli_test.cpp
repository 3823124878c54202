// Text hexray did not write (file names, scene keys and strings, a strip's stamp, a command-line
// word) reaches the terminal with its control characters escaped: a name can neither move the
// cursor, recolour the terminal nor retitle its window.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;
namespace fs = std::filesystem;

// An OSC that retitles the window (ESC ] ... BEL), a C1 CSI (U+009B) and a lone CSI byte.
constexpr const char* kRaw = "x\x1b]0;owned\x07\xc2\x9b\x9b";
constexpr const char* kEscaped = "x\\x1b]0;owned\\x07\\u009b\\x9b";

// The first control character in `text` (but a line's end), as a message for a failed test; ""
// for none. A C1 control counts both in UTF-8 (0xC2 0x80..0x9F) and as a lone byte.
std::string rawControl(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const bool c1 = c >= 0x80 && c <= 0x9f &&
                        (i == 0 || static_cast<unsigned char>(text[i - 1]) < 0x80 ||
                         static_cast<unsigned char>(text[i - 1]) == 0xc2);
        if ((c < 0x20 && c != '\n') || c == 0x7f || c1) {
            return "raw control character at byte " + std::to_string(i) + " in:\n" + text;
        }
    }
    return "";
}

class ControlCharacterTest : public CliTest {
protected:
    // Runs `arguments`, expects `escaped` in its output (stdout and stderr) and no raw control
    // character anywhere in it; returns the run.
    RunResult expectEscaped(const std::string& arguments, const std::string& escaped) const {
        const RunResult run = hexray(arguments);
        EXPECT_EQ(rawControl(run.out), "") << arguments;
        EXPECT_EQ(rawControl(run.err), "") << arguments;
        EXPECT_NE((run.out + run.err).find(escaped), std::string::npos) << arguments << "\n" << run.out << run.err;
        return run;
    }
    const std::string raw_ = kRaw;
    const std::string escaped_ = kEscaped;
};

TEST_F(ControlCharacterTest, SceneFileNamesAreEscaped) {
    expectEscaped("render '" + raw_ + ".json'", escaped_ + ".json: cannot read scene file");
    writeScene(raw_ + ".json", "{\"image\": {\"width\": 8}}");
    expectEscaped("render '" + raw_ + ".json'", escaped_ + ".json: image.height: missing required field");
    writeScene(raw_ + ".json", "{\"image\" 8}");
    expectEscaped("render '" + raw_ + ".json'", escaped_ + ".json:1:10: JSON syntax error");
}

TEST_F(ControlCharacterTest, SceneKeysStringsAndTheParsersQuotesAreEscaped) {
    writeScene("keys.json",
               "{\"im\x7f"
               "age\xc2\x9b\": 1}");
    expectEscaped("render keys.json", "keys.json: [\"im\\x7fage\\u009b\"]: unknown key");
    writeScene("strings.json", R"({"image": {"width": 8, "height": 8, "sampling": "cen)"
                               "\x7f"
                               R"(ter"}})");
    expectEscaped("render strings.json", "unknown value \"cen\\x7fter\"");
    writeScene("utf8.json", "{\"a\x9b\": 1}");  // not UTF-8: the parser quotes what it read
    expectEscaped("render utf8.json", "\\x9b");
}

TEST_F(ControlCharacterTest, OutputNamesAreEscapedInErrorsAndInTheSummary) {
    expectEscaped("render " + scene("lecture-demo.json") + " -o '" + raw_ + ".jpg'",
                  "-o " + escaped_ + ".jpg: unknown image format");
    expectEscaped("render " + scene("lecture-demo.json") + " --width 8 --height 8 -o '" + raw_ + ".png'",
                  "wrote " + escaped_ + ".png (8x8)");
    expectEscaped("render " + scene("lecture-demo.json") + " -o 'missing/" + raw_ + ".png'",
                  "missing/" + escaped_ + ".png: cannot create output file");
}

TEST_F(ControlCharacterTest, AStripStampAndPieceNamesAreEscaped) {
    {
        PngRowWriter piece(dir_ / "piece.png", 1, 1, {{"hexray-strip", "damaged " + raw_}});
        piece.writeRows(std::vector<std::uint8_t>(3, 0));
        piece.finish();
    }
    expectEscaped("merge out.png piece.png", "stamp is damaged (\"damaged " + escaped_ + "\")");
    expectEscaped("merge out.png '" + raw_ + ".png'", escaped_ + ".png");
}

TEST_F(ControlCharacterTest, CompareTablesAndCommandLineWordsAreEscaped) {
    fs::create_directories(dir_ / "scenes");
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scenes" / (raw_ + ".json"));
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scenes" / "plain.json");
    expectEscaped("compare scenes --width 8 --height 8", "| " + escaped_ + " |");
    expectEscaped("'" + raw_ + "'", "unknown command '" + escaped_ + "'");
    expectEscaped("render scene.json '--frob" + raw_ + "=1'", "unknown option '--frob" + escaped_ + "'");
}

}  // namespace
}  // namespace hexray
