// docs/scale-out.md: its manifests and scripts are valid YAML and shell, and the commands it
// gives each batch engine, run as N local processes with the engine's index variable set and then
// merged, make the single render.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

class ScaleOutCliTest : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        // What the doc's tasks take from the shared directory: a small scene, anti-aliased.
        std::string text = readFile(test::sourcePath("scenes/spheres-and-lights.json"));
        const std::string size = "\"width\": 960, \"height\": 540";
        ASSERT_NE(text.find(size), std::string::npos);
        text.replace(text.find(size), size.size(), "\"width\": 61, \"height\": 45, \"spp\": 2");
        writeScene("scene.json", text);
        const RunResult commands =
            shell("/usr/bin/python3 '" + test::sourcePath("tests/cli/scale_out_commands.py").string() + "' '" +
                  test::sourcePath("docs/scale-out.md").string() + "' .");
        ASSERT_EQ(commands.exitCode, 0) << commands.err;
        ASSERT_EQ(shell("\"$HEXRAY\" render scene.json -o single.png").exitCode, 0);
    }

    // Runs `stripScript` once per index with `variable` set to it, in parallel as the engine
    // would, then `mergeScript`; both with hexray on the PATH.
    RunResult runSplit(const std::string& variable, const std::string& stripScript, const std::string& mergeScript,
                       const std::string& strips) {
        const std::string path = "PATH=\"$(dirname \"$HEXRAY\"):$PATH\" SLURM_CPUS_PER_TASK=1";
        return shell("n=$(cat " + strips + "); pids=''; for i in $(seq 0 $((n - 1))); do " + path + " " + variable +
                     "=$i bash " + stripScript +
                     " & pids=\"$pids $!\"; done; for p in $pids; do wait $p || exit 9; "
                     "done; " +
                     path + " bash " + mergeScript);
    }
};

TEST_F(ScaleOutCliTest, TheIndexedJobsStripsMergeIntoTheSingleRender) {
    const RunResult run = runSplit("JOB_COMPLETION_INDEX", "k8s-strip.sh", "k8s-merge.sh", "k8s-strips");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(readFile(dir_ / "k8s-strips"), "8\n");
    EXPECT_TRUE(fs::exists(dir_ / "pieces" / "piece-7.png"));
    EXPECT_EQ(readPng(dir_ / "frame.png").bytes, readPng(dir_ / "single.png").bytes);
}

TEST_F(ScaleOutCliTest, TheSlurmArraysStripsMergeIntoTheSingleRender) {
    const RunResult run = runSplit("SLURM_ARRAY_TASK_ID", "slurm-strip.sh", "slurm-merge.sh", "slurm-strips");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(readFile(dir_ / "slurm-strips"), "8\n");
    EXPECT_EQ(readPng(dir_ / "frame.png").bytes, readPng(dir_ / "single.png").bytes);
}

TEST_F(ScaleOutCliTest, AMissingTaskMakesTheMergeFailNamingItsStrip) {
    const RunResult run = shell(
        "for i in 0 1 2 4 5 6 7; do PATH=\"$(dirname \"$HEXRAY\"):$PATH\" "
        "JOB_COMPLETION_INDEX=$i sh k8s-strip.sh || exit 9; done; "
        "PATH=\"$(dirname \"$HEXRAY\"):$PATH\" sh k8s-merge.sh");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("missing strip 3/8, rows 16-21"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "frame.png"));
}

}  // namespace
}  // namespace hexray
