// docs/scale-out.md: its manifests and scripts are valid YAML and shell and keep what a real
// cluster needs (a pinned renderer, threads from the CPU limit, a ReadWriteMany volume, a wait
// that ends on failure, afterany, a directory per run; scale_out_recipe_checks.py), and the
// commands it gives each batch engine, run as N local processes in the run's directory with the
// engine's variables set and then merged, make the single render.

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
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

constexpr const char* kRun = "20261126-120000-a1b2c3";

// A small scene, anti-aliased, for the doc's tasks to take from the shared directory.
std::string smallScene(const char* size) {
    std::string text = readFile(test::sourcePath("scenes/spheres-and-lights.json"));
    const std::string original = "\"width\": 960, \"height\": 540";
    text.replace(text.find(original), original.size(), size);
    return text;
}

// One batch engine as the doc drives it: the index variable and the prefix of the files
// scale_out_commands.py writes for it.
struct Engine {
    const char* name;
    const char* indexVariable;
    const char* files;
};

void PrintTo(const Engine& engine, std::ostream* out) {
    *out << engine.name;
}

// Runs scale_out_commands.py: checks `doc` and writes the commands of run `run` into `out`.
class ScaleOutDocTest : public CliTest {
protected:
    RunResult extractCommands(const fs::path& doc, const std::string& out, const std::string& run) const {
        std::string script = "/usr/bin/python3 '";
        script += test::sourcePath("tests/cli/scale_out_commands.py").string();
        return shell(script + "' '" + doc.string() + "' '" + out + "' '" + run + "'");
    }
};

class ScaleOutCliTest : public ScaleOutDocTest {
protected:
    void SetUp() override {
        ScaleOutDocTest::SetUp();
        writeScene("scene.json", smallScene("\"width\": 61, \"height\": 45, \"spp\": 2"));
        const RunResult commands = extractCommands(test::sourcePath("docs/scale-out.md"), ".", kRun);
        ASSERT_EQ(commands.exitCode, 0) << commands.err;
        ASSERT_EQ(shell("\"$HEXRAY\" render scene.json -o single.png").exitCode, 0);
    }

    // Puts `scene` into the run's directory, as the doc's run does before the tasks start, then
    // runs the engine's strip command once per index but `skipped` with the index variable set, in
    // parallel as the engine would, then its merge; all in the run's directory, hexray on the PATH.
    // `files` is where scale_out_commands.py wrote the engine's commands.
    RunResult runSplit(const Engine& engine, const std::string& scene, const std::string& files = ".",
                       int skipped = -1) const {
        const std::string prefix = files + "/" + engine.files;
        const std::string path = "PATH=\"$(dirname \"$HEXRAY\"):$PATH\"";
        return shell("top=$PWD; run=$(cat " + prefix + "-rundir); mkdir -p \"$run\" && cp " + scene +
                     " \"$run/scene.json\" && cd \"$run\" && n=$(cat \"$top/" + prefix +
                     "-strips\"); pids=''; for i in $(seq 0 $((n - 1))); do [ $i = " + std::to_string(skipped) +
                     " ] && continue; " + path + " " + engine.indexVariable + "=$i bash \"$top/" + prefix +
                     "-strip.sh\" & pids=\"$pids $!\"; done; for p in $pids; do wait $p || exit 9; done; " + path +
                     " bash \"$top/" + prefix + "-merge.sh\"");
    }

    fs::path runDirectory(const Engine& engine, const std::string& files = ".") const {
        std::string run = readFile(dir_ / files / (std::string(engine.files) + "-rundir"));
        run.pop_back();  // the newline
        return dir_ / run;
    }
};

class ScaleOutEngineTest : public ScaleOutCliTest, public ::testing::WithParamInterface<Engine> {};

TEST_P(ScaleOutEngineTest, TheStripsMergeIntoTheSingleRenderInTheRunsDirectory) {
    const RunResult run = runSplit(GetParam(), "scene.json");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(readFile(dir_ / (std::string(GetParam().files) + "-strips")), "8\n");
    EXPECT_EQ(runDirectory(GetParam()), dir_ / "runs" / kRun);
    EXPECT_TRUE(fs::exists(runDirectory(GetParam()) / "pieces" / "piece-7.png"));
    EXPECT_EQ(readPng(runDirectory(GetParam()) / "frame.png").bytes, readPng(dir_ / "single.png").bytes);
}

TEST_P(ScaleOutEngineTest, AMissingTaskMakesTheMergeFailNamingItsStrip) {
    const RunResult run = runSplit(GetParam(), "scene.json", ".", 3);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("missing strip 3/8, rows 16-21"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(runDirectory(GetParam()) / "frame.png"));
}

// A second run of an edited scene whose strip 3 failed: its merge names the strip missing, rather
// than finding the first run's piece 3, and the first run's frame stays as it was.
TEST_P(ScaleOutEngineTest, ASecondRunNeverSeesTheFirstRunsPieces) {
    ASSERT_EQ(runSplit(GetParam(), "scene.json").exitCode, 0);
    const std::string firstFrame = readFile(runDirectory(GetParam()) / "frame.png");
    writeScene("edited.json", smallScene("\"width\": 61, \"height\": 45, \"spp\": 1"));
    fs::create_directory(dir_ / "second");
    ASSERT_EQ(extractCommands(test::sourcePath("docs/scale-out.md"), "second", "20261126-120500-d4e5f6").exitCode, 0);
    const RunResult second = runSplit(GetParam(), "edited.json", "second", 3);
    EXPECT_EQ(second.exitCode, 2) << second.err;
    EXPECT_NE(second.err.find("missing strip 3/8, rows 16-21"), std::string::npos) << second.err;
    EXPECT_NE(runDirectory(GetParam(), "second"), runDirectory(GetParam()));
    EXPECT_EQ(readFile(runDirectory(GetParam()) / "frame.png"), firstFrame);
}

INSTANTIATE_TEST_SUITE_P(Engines, ScaleOutEngineTest,
                         ::testing::Values(Engine{"KubernetesIndexedJob", "JOB_COMPLETION_INDEX", "k8s"},
                                           Engine{"SlurmArray", "SLURM_ARRAY_TASK_ID", "slurm"}),
                         [](const auto& info) { return std::string(info.param.name); });

// The doc's run scripts, run against fake_cluster.py (kubectl and sbatch as local processes, the
// volume a directory here): the frame comes out, and a strip that fails on every attempt ends the
// run, its merge naming the strip, instead of a wait that never ends.
class ScaleOutRunTest : public ScaleOutCliTest {
protected:
    RunResult runOnFakeCluster(const std::string& script, const std::string& failingIndex = "") const {
        std::string fake = "'";
        fake += test::sourcePath("tests/cli/fake_cluster.py").string() + "'";
        return shell("mkdir -p bin volume state && ln -s " + fake + " bin/kubectl && ln -s " + fake +
                     " bin/sbatch && ln -s \"$HEXRAY\" bin/hexray && PATH=\"$PWD/bin:$PATH\" "
                     "FAKE_CLUSTER_VOLUME=\"$PWD/volume\" FAKE_CLUSTER_STATE=\"$PWD/state\" FAKE_CLUSTER_FAIL_INDEX=" +
                     failingIndex + " bash " + script + " scene.json");
    }

    // The files `directory/*/name` (name empty: the files in `directory` whose name starts with
    // `prefix`).
    std::vector<fs::path> found(const fs::path& directory, const std::string& prefix, const std::string& name) const {
        std::vector<fs::path> paths;
        if (!fs::exists(directory)) {
            return paths;
        }
        for (const auto& entry : fs::directory_iterator(directory)) {
            const fs::path path = name.empty() ? entry.path() : entry.path() / name;
            if (entry.path().filename().string().starts_with(prefix) && fs::is_regular_file(path)) {
                paths.push_back(path);
            }
        }
        return paths;
    }
};

TEST_F(ScaleOutRunTest, TheKubernetesRunCopiesTheFrameOut) {
    const RunResult run = runOnFakeCluster("k8s-run.sh");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("strips Complete, merge Complete"), std::string::npos) << run.out;
    const std::vector<fs::path> frames = found(dir_, "frame-", "");
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(readPng(frames[0]).bytes, readPng(dir_ / "single.png").bytes);
    EXPECT_EQ(found(dir_ / "volume" / "runs", "", "frame.png").size(), 1u);
}

TEST_F(ScaleOutRunTest, AKubernetesRunWhoseStripFailsEndsWithTheMergeNamingIt) {
    const RunResult run = runOnFakeCluster("k8s-run.sh", "3");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("missing strip 3/8, rows 16-21"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("strips Failed, merge Failed"), std::string::npos) << run.out;
    EXPECT_TRUE(found(dir_, "frame-", "").empty());
}

TEST_F(ScaleOutRunTest, TheSlurmRunMergesInItsDirectory) {
    const RunResult run = runOnFakeCluster("slurm-run.sh");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const std::vector<fs::path> frames = found(dir_ / "runs", "", "frame.png");
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(readPng(frames[0]).bytes, readPng(dir_ / "single.png").bytes);
    EXPECT_TRUE(fs::exists(frames[0].parent_path() / "strip-7.log"));
}

TEST_F(ScaleOutRunTest, ASlurmRunWhoseStripFailsStillMergesNamingIt) {
    const RunResult run = runOnFakeCluster("slurm-run.sh", "5");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    const std::vector<fs::path> logs = found(dir_ / "runs", "", "merge.log");
    ASSERT_EQ(logs.size(), 1u) << run.err;
    EXPECT_NE(readFile(logs[0]).find("missing strip 5/8, rows 28-32"), std::string::npos) << readFile(logs[0]);
    EXPECT_TRUE(found(dir_ / "runs", "", "frame.png").empty());
}

// What afterany is for: the same run with afterok would leave the merge pending, saying nothing.
TEST_F(ScaleOutRunTest, WithAfterOkASlurmRunWhoseStripFailsWouldNeverMerge) {
    ASSERT_EQ(shell("sed -i 's/afterany/afterok/' slurm-run.sh").exitCode, 0);
    const RunResult run = runOnFakeCluster("slurm-run.sh", "5");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.err.find("pending for ever: DependencyNeverSatisfied"), std::string::npos) << run.err;
    EXPECT_TRUE(found(dir_ / "runs", "", "merge.log").empty());
}

// One point a recipe must keep, taken out of the doc: the check names what is missing.
struct RemovedPoint {
    const char* name;
    const char* from;
    const char* to;
    const char* expectedMessage;
};

void PrintTo(const RemovedPoint& point, std::ostream* out) {
    *out << point.name;
}

class ScaleOutRecipeCheckTest : public ScaleOutDocTest, public ::testing::WithParamInterface<RemovedPoint> {};

TEST_P(ScaleOutRecipeCheckTest, FailsNamingThePoint) {
    const RemovedPoint& point = GetParam();
    std::string doc = readFile(test::sourcePath("docs/scale-out.md"));
    ASSERT_NE(doc.find(point.from), std::string::npos) << point.from;
    for (std::size_t at = doc.find(point.from); at != std::string::npos; at = doc.find(point.from, at)) {
        doc.replace(at, std::string(point.from).size(), point.to);
        at += std::string(point.to).size();
    }
    std::ofstream(dir_ / "changed.md") << doc;
    fs::create_directory(dir_ / "changed");
    const RunResult run = extractCommands(dir_ / "changed.md", "changed", kRun);
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.err.find(point.expectedMessage), std::string::npos)
        << "expected \"" << point.expectedMessage << "\" in:\n"
        << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "changed" / "k8s-strip.sh"));
}

INSTANTIATE_TEST_SUITE_P(
    Points, ScaleOutRecipeCheckTest,
    ::testing::Values(RemovedPoint{"KubernetesBackendLeftAtAuto", "--backend gpu --device llvmpipe --threads \"$LP",
                                   "--threads \"$LP", "Job hexray-strips-${RUN}: the renderer is not pinned"},
                      RemovedPoint{"SlurmBackendAuto", "--backend gpu --device llvmpipe --threads \"$SLURM",
                                   "--backend auto --threads \"$SLURM", "strips.sbatch: the renderer is not pinned"},
                      RemovedPoint{"KubernetesResources", "requests: {cpu: \"4\", memory: 2Gi}", "requests: {}",
                                   "Job hexray-strips-${RUN}: no resources requests.cpu, requests.memory"},
                      RemovedPoint{"LavapipeThreadsFromTheRequest", "resource: limits.cpu", "resource: requests.cpu",
                                   "Job hexray-strips-${RUN}: LP_NUM_THREADS does not come from its limits.cpu"},
                      RemovedPoint{"KubernetesThreadsOption", "--threads \"$LP_NUM_THREADS\" ", "",
                                   "hexray render is not given --threads \"$LP_NUM_THREADS\""},
                      RemovedPoint{"SlurmLavapipeThreads", "export LP_NUM_THREADS=\"$SLURM_CPUS_PER_TASK\"\n", "",
                                   "strips.sbatch: LP_NUM_THREADS does not come from SLURM_CPUS_PER_TASK"},
                      RemovedPoint{"SlurmMemory", "#SBATCH --mem=2G\n", "", "strips.sbatch: no #SBATCH --mem"},
                      RemovedPoint{"ReadWriteOnceVolume", "[ReadWriteMany]", "[ReadWriteOnce]",
                                   "PersistentVolumeClaim hexray-work: not ReadWriteMany"},
                      RemovedPoint{"NoVolumeClaim", "kind: PersistentVolumeClaim", "kind: ConfigMap",
                                   "no PersistentVolumeClaim defined"},
                      RemovedPoint{"VolumeNotMounted", "claimName: hexray-work", "claimName: scratch",
                                   "Job hexray-strips-${RUN}: does not mount the ReadWriteMany claim"},
                      RemovedPoint{"WaitForCompleteAlone", "strips=$(job_outcome \"hexray-strips-$run\")",
                                   "kubectl wait --for=condition=complete job/hexray-strips-$run --timeout=2h",
                                   "waits with --for=condition=complete alone"},
                      RemovedPoint{"WaitIgnoresFailed", "*\" Failed \"*) echo Failed; return ;;", "",
                                   "does not stop waiting when a Job is Failed"},
                      RemovedPoint{"NoSceneCopiedIn", "kubectl cp \"$scene\"", "echo \"$scene\"",
                                   "does not copy the scene in (kubectl cp)"},
                      RemovedPoint{"SharedRetries", "backoffLimitPerIndex: 2", "backoffLimit: 2",
                                   "Job hexray-strips-${RUN}: no backoffLimitPerIndex"},
                      RemovedPoint{"KubernetesSharedDirectory", "workingDir: /work/runs/${RUN}", "workingDir: /work",
                                   "Job hexray-strips-${RUN}: its workingDir has no ${RUN}"},
                      RemovedPoint{"KubernetesSharedJobName", "name: hexray-strips-${RUN}", "name: hexray-strips",
                                   "its name has no ${RUN}"},
                      RemovedPoint{"SlurmAfterOk",
                                   "--dependency=afterany:", "--dependency=afterok:", "--dependency=afterany"},
                      RemovedPoint{"SlurmSharedDirectory", "--chdir=\"runs/$run\" strips", "strips",
                                   "the Slurm strips job does not run in the run's directory"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hexray
