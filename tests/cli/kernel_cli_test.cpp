// The generated kernel through the real executable: `render` says how its kernel was made (written,
// compiled by glslang or loaded from the kernel cache under $XDG_CACHE_HOME/hexray) and how long the
// driver's compile took; a corrupt, spliced or refused cache file, or a FIFO in its place, is
// reported, compiled afresh and rewritten, and an unusable cache is no cache; the cache keeps its
// bound, and `hexray cache` shows and clears it; culling by tile classes leaves the image as it was.

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"

namespace hexray::test {
namespace {

class KernelCliTest : public CliTest {
protected:
    RunResult renderDemo(const std::string& cacheHome) {
        return hexray("render " + scene("lecture-demo.json") + " -o demo.png --width 40 --height 30",
                      "XDG_CACHE_HOME='" + cacheHome + "'");
    }
    // Renders `sceneName` to `output` with the test's own cache (and `environment` besides).
    RunResult render(const std::string& sceneName, const std::string& output, const std::string& environment = "") {
        return hexray("render " + scene(sceneName) + " -o " + output + " --width 40 --height 30 --backend gpu",
                      "XDG_CACHE_HOME='" + (dir_ / "cache").string() + "' " + environment);
    }
    // The one report of a bad entry: a note naming the file and the reason.
    static bool reportsOnly(const std::string& err, const fs::path& file, const std::string& reason) {
        const std::string line = "hexray: note: kernel cache entry '" + file.string() + "' removed: " + reason;
        return err.starts_with(line) && std::count(err.begin(), err.end(), '\n') == 1;
    }
    std::vector<fs::path> cacheFiles() const {
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(dir_ / "cache" / "hexray")) {
            files.push_back(entry.path());
        }
        return files;
    }
};

TEST_F(KernelCliTest, RenderSaysHowItsKernelWasMadeAndCachesIt) {
    const RunResult first = renderDemo((dir_ / "cache").string());
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_NE(first.out.find("kernel generated for the scene, written in"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("glslang"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("first dispatch"), std::string::npos) << first.out;
    ASSERT_EQ(cacheFiles().size(), 1u);

    const RunResult second = renderDemo((dir_ / "cache").string());
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_NE(second.out.find("SPIR-V from the kernel cache"), std::string::npos) << second.out;
    EXPECT_EQ(readFile(dir_ / "demo.png").size() > 0, true);
}

TEST_F(KernelCliTest, ACorruptCacheFileIsCompiledAgainAndRewritten) {
    ASSERT_EQ(renderDemo((dir_ / "cache").string()).exitCode, 0);
    const fs::path file = cacheFiles().front();
    std::ofstream(file, std::ios::binary | std::ios::trunc) << "not a kernel";
    const RunResult again = renderDemo((dir_ / "cache").string());
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.out.find("glslang"), std::string::npos) << again.out;
    EXPECT_GT(fs::file_size(file), 100u);  // whole again
    EXPECT_NE(renderDemo((dir_ / "cache").string()).out.find("SPIR-V from the kernel cache"), std::string::npos);
}

TEST_F(KernelCliTest, OneScenesKeyWithAnothersSpirvIsAMissNotTheOtherImage) {
    ASSERT_EQ(render("lecture-demo.json", "a.png").exitCode, 0);
    const fs::path first = cacheFiles().front();
    const std::string firstBytes = readFile(first);
    ASSERT_EQ(render("spheres-and-lights.json", "b.png").exitCode, 0);
    ASSERT_EQ(cacheFiles().size(), 2u);
    const fs::path second = cacheFiles()[cacheFiles()[0] == first ? 1 : 0];
    const std::string secondBytes = readFile(second);
    // Each entry's SPIR-V starts with its magic number, after its 8-byte word count: the first
    // entry's key with the second's SPIR-V.
    const std::string spirvMagic("\x03\x02\x23\x07", 4);
    const std::size_t firstSpirv = firstBytes.find(spirvMagic) - 8;
    const std::size_t secondSpirv = secondBytes.find(spirvMagic) - 8;
    std::ofstream(first, std::ios::binary | std::ios::trunc)
        << firstBytes.substr(0, firstSpirv) + secondBytes.substr(secondSpirv);

    const RunResult again = render("lecture-demo.json", "again.png");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(readFile(dir_ / "again.png"), readFile(dir_ / "a.png"));
    EXPECT_TRUE(reportsOnly(again.err, first, "its SHA-256 checksum does not match its contents")) << again.err;
    EXPECT_NE(again.out.find("glslang"), std::string::npos) << again.out;
    EXPECT_EQ(readFile(first), firstBytes);  // rewritten
}

TEST_F(KernelCliTest, AFifoAtAnEntrysNameIsAMissNotAHang) {
    ASSERT_EQ(render("lecture-demo.json", "a.png").exitCode, 0);
    const fs::path file = cacheFiles().front();
    const std::string bytes = readFile(file);
    fs::remove(file);
    ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
    const RunResult again = render("lecture-demo.json", "again.png");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_TRUE(reportsOnly(again.err, file, "it is a FIFO, not a regular file")) << again.err;
    EXPECT_EQ(readFile(dir_ / "again.png"), readFile(dir_ / "a.png"));
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(file)));
    EXPECT_EQ(readFile(file), bytes);
}

TEST_F(KernelCliTest, SpirvFromTheCacheThatTheDriverRefusesIsCompiledAfresh) {
    // The injected fault fails the process's first pipeline creation, as a driver that cannot
    // take the SPIR-V would; from the cache, that is a miss: the entry is removed and rewritten.
    ASSERT_EQ(render("lecture-demo.json", "a.png").exitCode, 0);
    const fs::path file = cacheFiles().front();
    const std::string bytes = readFile(file);
    const std::string fault = "HEXRAY_INJECT_VULKAN_FAULT=pipeline-fails-once";
    const RunResult refused = render("lecture-demo.json", "refused.png", fault);
    ASSERT_EQ(refused.exitCode, 0) << refused.err;
    EXPECT_TRUE(
        reportsOnly(refused.err, file, "the driver refused its SPIR-V (vkCreateComputePipelines: ErrorUnknown)"))
        << refused.err;
    EXPECT_NE(refused.out.find("glslang"), std::string::npos) << refused.out;
    EXPECT_EQ(readFile(dir_ / "refused.png"), readFile(dir_ / "a.png"));
    EXPECT_EQ(readFile(file), bytes);
    EXPECT_NE(render("lecture-demo.json", "c.png").out.find("SPIR-V from the kernel cache"), std::string::npos);

    // Fresh SPIR-V that the driver refuses is an error, tried once.
    fs::remove_all(dir_ / "cache");
    const RunResult fresh = render("lecture-demo.json", "fresh.png", fault);
    EXPECT_EQ(fresh.exitCode, 3) << fresh.err;
    EXPECT_NE(fresh.err.find("hexray: error: Vulkan failed while rendering: vkCreateComputePipelines: ErrorUnknown"),
              std::string::npos)
        << fresh.err;
    EXPECT_FALSE(fs::exists(dir_ / "fresh.png"));
}

TEST_F(KernelCliTest, TheCacheKeepsItsBound) {
    // A bound of one byte keeps only the entry just stored.
    const std::string bound = "HEXRAY_KERNEL_CACHE_MAX_SIZE=1";
    ASSERT_EQ(render("lecture-demo.json", "a.png", bound).exitCode, 0);
    const fs::path first = cacheFiles().front();
    ASSERT_EQ(render("spheres-and-lights.json", "b.png", bound).exitCode, 0);
    ASSERT_EQ(cacheFiles().size(), 1u);
    EXPECT_NE(cacheFiles().front(), first);
    EXPECT_EQ(render("lecture-demo.json", "a.png", "HEXRAY_KERNEL_CACHE_MAX_SIZE=0").out.find("kernel cache"),
              std::string::npos);  // 0: no cache at all
    EXPECT_EQ(cacheFiles().size(), 1u);

    const RunResult bad = render("lecture-demo.json", "bad.png", "HEXRAY_KERNEL_CACHE_MAX_SIZE=lots");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("hexray: error: HEXRAY_KERNEL_CACHE_MAX_SIZE: must be a size in bytes"), std::string::npos)
        << bad.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
}

TEST_F(KernelCliTest, TheCacheCommandSaysWhereTheCacheIsWhatItHoldsAndClearsIt) {
    const std::string cacheHome = "XDG_CACHE_HOME='" + (dir_ / "cache").string() + "'";
    ASSERT_EQ(render("lecture-demo.json", "a.png").exitCode, 0);
    const std::uintmax_t bytes = fs::file_size(cacheFiles().front());
    const RunResult shown = hexray("cache", cacheHome);
    ASSERT_EQ(shown.exitCode, 0) << shown.err;
    char size[32];
    std::snprintf(size, sizeof size, "%.1f MiB", double(bytes) / double(1 << 20));
    EXPECT_EQ(shown.out, "kernel cache: " + (dir_ / "cache" / "hexray").string() + "\n1 entry, " + size +
                             " of at most 128 MiB (HEXRAY_KERNEL_CACHE_MAX_SIZE sets the bound)\n");
    EXPECT_EQ(shown.err, "");
    EXPECT_NE(hexray("cache", cacheHome + " HEXRAY_KERNEL_CACHE_MAX_SIZE=1G").out.find("of at most 1024 MiB"),
              std::string::npos);

    const RunResult cleared = hexray("cache --clear", cacheHome);
    ASSERT_EQ(cleared.exitCode, 0) << cleared.err;
    EXPECT_EQ(cleared.out,
              "kernel cache: " + (dir_ / "cache" / "hexray").string() + "\nremoved 1 entry, " + size + "\n");
    EXPECT_TRUE(cacheFiles().empty());
    EXPECT_NE(render("lecture-demo.json", "a.png").out.find("glslang"), std::string::npos);

    const RunResult none = hexray("cache", "env -u XDG_CACHE_HOME -u HOME");
    EXPECT_EQ(none.exitCode, 0) << none.err;
    EXPECT_EQ(none.out, "kernel cache: none (neither XDG_CACHE_HOME nor HOME is set)\n");
}

TEST_F(KernelCliTest, AnUnusableCacheIsNoCacheAndNoError) {
    std::ofstream(dir_ / "not-a-directory") << "x";
    const RunResult run = renderDemo((dir_ / "not-a-directory").string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("hexray:"), std::string::npos) << run.err;  // (Mesa says its own cache is off)
    EXPECT_NE(run.out.find("glslang"), std::string::npos) << run.out;
}

TEST_F(KernelCliTest, TwoProcessesSharingTheCacheBothSucceed) {
    const std::string cache = (dir_ / "cache").string();
    const std::string render =
        "'" + hexrayExecutable() + "' render " + scene("lecture-demo.json") + " --width 40 --height 30 -o ";
    const std::string command = "cd '" + dir_.string() + "' && export XDG_CACHE_HOME='" + cache + "' && (" + render +
                                "a.png >/dev/null & " + render + "b.png >/dev/null & wait) && cmp a.png b.png";
    EXPECT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(cacheFiles().size(), 1u);  // one whole file, no temporary left
}

TEST_F(KernelCliTest, CullingRendersTheSameImageWithAKernelPerTileClass) {
    const std::string demo = "render " + scene("lecture-demo.json") + " --width 200 --height 150 ";
    const RunResult culled = hexray(demo + "--culling on -o on.png");
    ASSERT_EQ(culled.exitCode, 0) << culled.err;
    EXPECT_NE(culled.out.find("tile classes"), std::string::npos) << culled.out;
    const RunResult whole = hexray(demo + "--culling off -o off.png");
    ASSERT_EQ(whole.exitCode, 0) << whole.err;
    EXPECT_EQ(whole.out.find("tile classes"), std::string::npos) << whole.out;
    EXPECT_EQ(readFile(dir_ / "on.png"), readFile(dir_ / "off.png"));
    // A small render is not worth the extra kernels' compile: auto leaves it whole.
    EXPECT_EQ(hexray(demo + "-o auto.png").out.find("tile classes"), std::string::npos);
    EXPECT_EQ(hexray(demo + "--culling maybe -o x.png").exitCode, 2);
}

}  // namespace
}  // namespace hexray::test
