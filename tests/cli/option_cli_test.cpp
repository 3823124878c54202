// Numbers and paths on the command line, checked as strictly as the scene file's: each bad value
// is exit code 2 with a message naming the option and its range, before any work; the values
// echoed are the values used.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"

namespace hexray {
namespace {

using test::RunResult;

struct BadOption {
    const char* name;
    const char* command;  // after `hexray`; SCENE stands for the lecture demo
    const char* message;
};

void PrintTo(const BadOption& bad, std::ostream* out) {
    *out << bad.name;
}

class BadOptionTest : public test::CliTest, public ::testing::WithParamInterface<BadOption> {};

TEST_P(BadOptionTest, IsExitCode2NamingTheOptionAndItsRangeBeforeAnyWork) {
    std::string command = GetParam().command;
    command.replace(command.find("SCENE"), 5, scene("lecture-demo.json"));
    const RunResult run = hexray(command + " --width 8 --height 8");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    EXPECT_NE(run.err.find(std::string("hexray: error: ") + GetParam().message), std::string::npos)
        << "expected \"" << GetParam().message << "\" in:\n"
        << run.err;
    EXPECT_LT(run.err.size(), 300u) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(
    Options, BadOptionTest,
    ::testing::Values(
        BadOption{"NegativeMismatchCount", "compare SCENE --max-topology-mismatches -1",
                  "--max-topology-mismatches: must be an integer between 0 and 18446744073709551615 (got -1)"},
        BadOption{"RmseNan", "compare SCENE --max-rmse nan",
                  "--max-rmse: must be a finite number between 0 and 255 (got nan)"},
        BadOption{"RmseInfinite", "compare SCENE --max-rmse inf",
                  "--max-rmse: must be a finite number between 0 and 255 (got inf)"},
        BadOption{"BadPixelsNan", "compare SCENE --max-bad-pixels nan",
                  "--max-bad-pixels: must be a finite number between 0 and 100 (got nan)"},
        BadOption{"AmbiguousNan", "compare SCENE --max-ambiguous nan",
                  "--max-ambiguous: must be a finite number between 0 and 100 (got nan)"},
        BadOption{"AmbiguousAbove100", "compare SCENE --max-ambiguous 100.5",
                  "--max-ambiguous: must be a finite number between 0 and 100 (got 100.5)"},
        BadOption{"FrameSecondsNan", "bench SCENE --rounds 1 --samples 1 --reference-samples 1 --max-frame-seconds nan",
                  "--max-frame-seconds: must be a finite number greater than 0 (got nan)"},
        BadOption{"FrameSecondsInfinite", "bench SCENE --rounds 1 --max-frame-seconds inf",
                  "--max-frame-seconds: must be a finite number greater than 0 (got inf)"},
        BadOption{"ThreadsZero", "render SCENE -o x.png --backend cpu --threads 0",
                  "--threads: must be an integer between 1 and 4294967295 (got 0)"},
        BadOption{"ThreadsNegative", "compare SCENE --threads -2",
                  "--threads: must be an integer between 1 and 4294967295 (got -2)"},
        BadOption{"WidthInHex", "render SCENE -o x.png --backend cpu --width 0x10",
                  "--width: must be an integer between 1 and 16384 (got 0x10)"},
        BadOption{"WidthWithSpace", "render SCENE -o x.png --backend cpu --width ' 12'",
                  "--width: must be an integer between 1 and 16384 (got  12)"},
        BadOption{"HugeWidthEchoedAsGiven", "render SCENE -o x.png --backend cpu --width 99999999999999999999",
                  "--width: must be an integer between 1 and 16384 (got 99999999999999999999)"},
        BadOption{"SamplesFraction", "render SCENE -o x.png --spp 1.5",
                  "--spp: must be an integer between 1 and 1024 (got 1.5)"},
        BadOption{"PixelSampleNegative", "pixel SCENE 1 1 --sample -1",
                  "--sample: must be an integer between 0 and 1023 (got -1)"},
        BadOption{"RoundsZero", "bench SCENE --rounds 0", "--rounds: must be an integer between 1 and 1000 (got 0)"},
        BadOption{"EmptyOutput", "render SCENE -o ''", "--output: must not be empty"},
        BadOption{"EmptyDiff", "compare SCENE --diff ''", "--diff: must not be empty"},
        BadOption{"EmptyCsv", "bench SCENE --csv ''", "--csv: must not be empty"},
        BadOption{"EmptyAov", "render SCENE -o x.png --aov ''", "--aov: must not be empty"},
        // A named value is one of its names, never the enum's number behind it.
        BadOption{"BackendUnknown", "render SCENE -o x.png --backend vulkan",
                  "--backend: vulkan not in {auto,gpu,cpu}"},
        BadOption{"BackendByNumber", "render SCENE -o x.png --backend 2", "--backend: 2 not in {auto,gpu,cpu}"},
        BadOption{"CullingUnknown", "render SCENE -o x.png --culling yes", "--culling: yes not in {auto,on,off}"},
        BadOption{"PrecisionByNumber", "compare SCENE --precision 1",
                  "--precision: 1 not in {auto,f32,f64,f32-naive,f32-certified}"},
        BadOption{"PixelBackendUnknown", "pixel SCENE 1 1 --backend auto", "--backend: auto not in {both,gpu,cpu}"}),
    [](const auto& info) { return std::string(info.param.name); });

using OptionCliTest = test::CliTest;

TEST_F(OptionCliTest, ThreadsBeyondWhatIsUsedAreCappedAndTheCapIsEchoed) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") +
                                 " -o x.png --backend cpu --width 16 --height 8 --threads 4000000000");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("cpu reference (8 threads)"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("4000000000"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace hexray
