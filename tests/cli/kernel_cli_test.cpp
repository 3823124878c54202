// The generated kernel through the real executable: `render` says how its kernel was made (written,
// compiled by glslang or loaded from the kernel cache under $XDG_CACHE_HOME/hexray) and how long the
// driver's compile took; a corrupt cache file is rewritten, and an unusable cache is no cache;
// culling by tile classes leaves the image as it was.

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

TEST_F(KernelCliTest, AnUnusableCacheIsNoCacheAndNoError) {
    std::ofstream(dir_ / "not-a-directory") << "x";
    const RunResult run = renderDemo((dir_ / "not-a-directory").string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("hexray:"), std::string::npos) << run.err;  // (Mesa says its own cache is off)
    EXPECT_NE(run.out.find("glslang"), std::string::npos) << run.out;
}

TEST_F(KernelCliTest, TwoProcessesSharingTheCacheBothSucceed) {
    const std::string cache = (dir_ / "cache").string();
    const std::string render = "'" HEXRAY_EXECUTABLE "' render " + scene("lecture-demo.json") +
                               " --width 40 --height 30 -o ";
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
