// A command line that looks like one program: help that fits 100 columns with an example per
// command, CLI11's parse errors in hexray's words (with "did you mean …"), --quiet, and no image
// written onto a terminal.

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;

const std::vector<std::string> kCommands = {"render", "merge", "compare", "diff", "bench", "pixel", "devices", "cache"};

// Columns on a terminal: UTF-8 continuation bytes take none.
std::size_t columns(const std::string& line) {
    std::size_t count = 0;
    for (const char c : line) {
        count += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
    }
    return count;
}

TEST_F(CliTest, EveryHelpLineFitsIn100ColumnsAndEveryCommandShowsAnExample) {
    std::vector<std::string> commands = {""};
    commands.insert(commands.end(), kCommands.begin(), kCommands.end());
    for (const std::string& command : commands) {
        const RunResult run = hexray(command + " --help");
        ASSERT_EQ(run.exitCode, 0) << command << run.err;
        std::istringstream lines(run.out);
        for (std::string line; std::getline(lines, line);) {
            EXPECT_LE(columns(line), 100u) << "hexray " << command << " --help:\n" << line;
        }
        if (!command.empty()) {
            EXPECT_NE(run.out.find("\nExample:\n  hexray " + command + " "), std::string::npos) << run.out;
            EXPECT_NE(run.out.find("\nExit codes: hexray --help lists them.\n"), std::string::npos) << run.out;
            EXPECT_EQ(run.out.find("  0  success"), std::string::npos) << run.out;  // the table once, below
        }
    }
}

TEST_F(CliTest, TheExitCodeTableIsInTheTopLevelHelp) {
    const RunResult run = hexray("--help");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("Exit codes:\n  0  success\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("\n  9  diff: the two images differ in size\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("-q,--quiet"), std::string::npos) << run.out;
}

struct Misuse {
    const char* name;
    const char* command;  // after `hexray`; SCENE stands for the lecture demo
    const char* message;  // the whole of standard error
};

void PrintTo(const Misuse& misuse, std::ostream* out) {
    *out << misuse.name;
}

class MisuseTest : public CliTest, public ::testing::WithParamInterface<Misuse> {};

TEST_P(MisuseTest, IsOneLineInHexraysWordsAndExitCode2) {
    std::string command = GetParam().command;
    if (const std::size_t at = command.find("SCENE"); at != std::string::npos) {
        command.replace(at, 5, scene("lecture-demo.json"));
    }
    const RunResult run = hexray(command);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_EQ(run.err, std::string("hexray: error: ") + GetParam().message + "\n");
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(
    CommandLine, MisuseTest,
    ::testing::Values(
        Misuse{"CommandMisspelt", "rendr SCENE",
               "unknown command 'rendr'; did you mean render? (hexray --help describes the commands)"},
        Misuse{"CommandUnknown", "frobnicate SCENE",
               "unknown command 'frobnicate' (the commands are render, watch, merge, compare, diff, bench, pixel, "
               "devices, "
               "cache; hexray --help describes them)"},
        Misuse{"OptionMisspelt", "render SCENE --widht 8",
               "unknown option '--widht' for render; did you mean --width? (hexray render --help describes the "
               "options)"},
        Misuse{"OptionMisspeltWithItsValue", "compare SCENE --max-rmes=2",
               "unknown option '--max-rmes' for compare; did you mean --max-rmse? (hexray compare --help describes "
               "the options)"},
        Misuse{"GlobalOptionMisspeltAfterTheCommand", "render SCENE --quite",
               "unknown option '--quite' for render; did you mean --quiet? (hexray render --help describes the "
               "options)"},
        Misuse{"GlobalOptionMisspelt", "--validat render SCENE",
               "unknown option '--validat' for render; did you mean --validate? (hexray render --help describes "
               "the options)"},
        Misuse{"GlobalOptionMisspeltWithoutACommand", "--validat",
               "unknown option '--validat'; did you mean --validate? (hexray --help describes the options)"},
        Misuse{"OptionUnknown", "render SCENE --frobnicate",
               "unknown option '--frobnicate' for render (hexray render --help describes the options)"},
        Misuse{"ArgumentTooMany", "pixel SCENE 1 2 3",
               "unexpected argument '3' for pixel (usage: hexray pixel [OPTIONS] scene x y)"},
        Misuse{"ArgumentMissing", "pixel SCENE 1",
               "pixel needs its y argument (usage: hexray pixel [OPTIONS] scene x y)"},
        Misuse{"ScenesMissing", "render -o x.png",
               "render needs its scenes argument (usage: hexray render [OPTIONS] scenes...)"},
        Misuse{"ValueMissing", "render SCENE --width", "--width needs a value (hexray render --help describes it)"},
        Misuse{"OptionsThatExcludeEachOther", "compare SCENE --all --precision f32",
               "--precision and --all cannot be given together"},
        Misuse{"NamedValueMisspelt", "render SCENE --backend gpuu",
               "--backend: gpuu not in {auto,gpu,cpu}; did you mean gpu?"},
        Misuse{
            "NoCommand", "--validate",
            "a command is required: render, watch, merge, compare, diff, bench, pixel, devices, cache (hexray --help "
            "describes them)"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(CliTest, QuietLeavesNoProgressAndNoSummaryButTheImagesAndTheErrors) {
    const std::string small = " --width 24 --height 16";
    for (const std::string& line : std::vector<std::string>{
             "render " + scene("lecture-demo.json") + small + " -o q.png -q",
             "--quiet render " + scene("lecture-demo.json") + small + " -o q.png --backend cpu",
             "render " + scene("lecture-demo.json") + small + " -o strip.png --strip 0/1 --quiet --backend cpu",
             "merge -q merged.png strip.png",
             "compare -q " + scene("lecture-demo.json") + small + " --max-ambiguous 100",
             "diff --quiet q.png merged.png"}) {
        const RunResult run = hexray(line);
        EXPECT_EQ(run.exitCode, 0) << line << "\n" << run.err;
        EXPECT_EQ(run.out, "") << line;
        EXPECT_EQ(run.err, "") << line;
    }
    EXPECT_TRUE(std::filesystem::exists(dir_ / "q.png"));
    EXPECT_TRUE(std::filesystem::exists(dir_ / "merged.png"));
    const RunResult missing = hexray("render missing.json -q");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("hexray: error: "), std::string::npos) << missing.err;
    EXPECT_EQ(missing.out, "");
}

TEST_F(CliTest, TheSummaryLineShowsTheWallTimeAndItsParts) {
    RunResult run = hexray("render " + scene("lecture-demo.json") + " --width 24 --height 16 -o t.png --backend gpu");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string ms = "\\d+\\.\\d";
    EXPECT_TRUE(std::regex_search(
        run.out, std::regex("; " + ms + " ms in all \\(start-up " + ms + ", load " + ms + ", kernel " + ms +
                            ", render " + ms + ", write " + ms + ", other " + ms + "\\)\n$")))
        << run.out;
    EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << run.out;
    run = hexray("render " + scene("lecture-demo.json") + " --width 24 --height 16 -o t.png --backend cpu");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("; " + ms + " ms in all \\(load " + ms + ", render " + ms +
                                                      ", write " + ms + ", other " + ms + "\\)\n$")))
        << run.out;
}

// Standard output a terminal: `script` gives the command a pseudo-terminal.
class TerminalCliTest : public CliTest {
protected:
    RunResult onTerminal(const std::string& arguments) const {
        return shell("script -qec \"\\\"$HEXRAY\\\" " + arguments + "\" /dev/null");
    }
};

TEST_F(TerminalCliTest, AnImageIsNotWrittenOntoATerminal) {
    const std::string small = scene("lecture-demo.json") + " --width 24 --height 16";
    ASSERT_EQ(hexray("render " + small + " -o piece.png --strip 0/1").exitCode, 0);
    const struct {
        std::string command;
        std::string message;
    } refused[] = {
        {"render " + small + " -o -",
         "-o -: standard output is a terminal, and an image is not text: pipe it (... | "
         "display) or give -o FILE"},
        {"render " + small + " -o /dev/stdout", "-o /dev/stdout: standard output is a terminal"},
        {"merge - piece.png",
         "the output -: standard output is a terminal, and an image is not text: pipe it (... "
         "| display) or give a file name"},
        {"compare " + small + " --diff -", "--diff -: standard output is a terminal"},
        {"compare " + small + " --mask -", "--mask -: standard output is a terminal"},
        {"diff piece.png piece.png --heatmap -", "--heatmap -: standard output is a terminal"},
    };
    for (const auto& [command, message] : refused) {
        const RunResult run = onTerminal(command);
        EXPECT_EQ(run.exitCode, 2) << command << "\n" << run.out;
        EXPECT_NE(run.out.find("hexray: error: " + message), std::string::npos) << run.out;
        EXPECT_EQ(run.out.find("PNG"), std::string::npos) << command;
    }
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"piece.png"});
    // Piped, it is written; the report goes to standard error, the terminal.
    const RunResult piped = shell("script -qec \"\\\"$HEXRAY\\\" render " + small + " -o - > piped.png\" /dev/null");
    EXPECT_EQ(piped.exitCode, 0) << piped.out;
    EXPECT_EQ(test::readFile(dir_ / "piped.png").substr(1, 3), "PNG");
}

TEST_F(TerminalCliTest, QuietShowsNoProgressOnATerminal) {
    const RunResult run = onTerminal("render " + scene("lecture-demo.json") +
                                     " --backend cpu --width 200 --height 1500 -o c.png --quiet");
    ASSERT_EQ(run.exitCode, 0) << run.out;
    EXPECT_EQ(run.out, "");
}

}  // namespace
}  // namespace hexray
