// Memory bounded by the image's width, not its area, through the real executable under an
// address-space limit (`ulimit -v`); and running out of memory is a message that says which
// size to reduce. (The peak figures themselves are in docs/memory.md; a test asserts limits only.)

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"

namespace hexray {
namespace {

using test::RunResult;
namespace fs = std::filesystem;

// Nothing to hit: the cheapest pixels, so that a large image renders in seconds on the CPU.
constexpr const char* kEmptyScene =
    R"({"image": {"width": 64, "height": 64}, "camera": {"position": [0, 1, 0]}, "background": [0.2, 0.3, 0.4],
        "nodes": []})";

class MemoryCliTest : public test::CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        writeScene("empty.json", kEmptyScene);
    }

    RunResult underLimit(std::uint64_t kibibytes, const std::string& arguments) const {
        return shell("ulimit -v " + std::to_string(kibibytes) + " && \"$HEXRAY\" " + arguments);
    }

    // The smallest limit (KiB, to a MiB) under which `arguments` succeed, found by bisection.
    std::uint64_t smallestWorkingLimit(const std::string& arguments) const {
        std::uint64_t failing = 1024;
        std::uint64_t working = std::uint64_t{4} << 20;
        const RunResult generous = underLimit(working, arguments);
        EXPECT_EQ(generous.exitCode, 0) << generous.err;
        while (working - failing > 1024) {
            const std::uint64_t middle = (failing + working) / 2;
            (underLimit(middle, arguments).exitCode == 0 ? working : failing) = middle;
        }
        return working;
    }

    // Width and height from a PNG's header, without decoding the image.
    static std::pair<std::uint32_t, std::uint32_t> pngSize(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        unsigned char header[24] = {};
        in.read(reinterpret_cast<char*>(header), sizeof header);
        const auto bigEndian = [&](int at) {
            return std::uint32_t(header[at]) << 24 | std::uint32_t(header[at + 1]) << 16 |
                   std::uint32_t(header[at + 2]) << 8 | std::uint32_t(header[at + 3]);
        };
        return {bigEndian(16), bigEndian(20)};
    }
};

TEST_F(MemoryCliTest, ACpuRenderOf8192SquaredFitsInAGigabyteOfAddressSpace) {
    const RunResult run = underLimit(1000000, "render empty.json --backend cpu --width 8192 --height 8192 -o big.png");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(pngSize(dir_ / "big.png"), std::make_pair(8192u, 8192u));
}

TEST_F(MemoryCliTest, CompareOf4096SquaredWithItsImagesFitsInAGigabyteOfAddressSpace) {
    const RunResult run =
        underLimit(1000000, "compare empty.json --width 4096 --height 4096 --diff diff.png --mask mask.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("PASS"), std::string::npos) << run.out;
    EXPECT_EQ(pngSize(dir_ / "diff.png"), std::make_pair(4096u, 4096u));
    EXPECT_EQ(pngSize(dir_ / "mask.png"), std::make_pair(4096u, 4096u));
}

TEST_F(MemoryCliTest, AovsOf4096SquaredFitInAGigabyteOfAddressSpace) {
    for (const std::string backend : {"gpu", "cpu"}) {
        const RunResult run = underLimit(1000000, "render empty.json --backend " + backend +
                                                      " --width 4096 --height 4096 -o x.png --aov aov-" + backend);
        ASSERT_EQ(run.exitCode, 0) << backend << ": " << run.err;
        EXPECT_EQ(pngSize(dir_ / ("aov-" + backend) / "depth.png"), std::make_pair(4096u, 4096u));
    }
}

// A scene file of `lights` lights and nothing to light, written compactly.
std::uint64_t writeManyLights(const fs::path& path, std::size_t lights) {
    std::ofstream out(path);
    out << R"({"image": {"width": 16, "height": 16}, "camera": {"position": [0, 1, 0]}, "nodes": [], "lights": [)";
    for (std::size_t i = 0; i < lights; ++i) {
        out << (i ? "," : "") << R"({"position":[)" << i % 1000 << ".5," << 10 + i % 7 << "," << i / 1000
            << R"(.25],"intensity":1.5})";
    }
    out << "]}";
    out.close();
    return fs::file_size(path);
}

TEST_F(MemoryCliTest, AFileOfManyLightsLoadsInAFewTimesItsSizeOfAddressSpace) {
    // The lights are read one at a time, not held as a document (some 700 bytes a light, over ten
    // times the file), and kept in chunks that never move while the file is read.
    const std::uint64_t baseline =
        smallestWorkingLimit("render empty.json --backend cpu --threads 1 --width 1 --height 1 -o tiny.png");
    const std::uint64_t fileKiB = writeManyLights(dir_ / "lights.json", 350000) / 1024;
    const RunResult run =
        underLimit(baseline + 5 * fileKiB, "render lights.json --backend cpu --threads 1 -o lights.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(pngSize(dir_ / "lights.png"), std::make_pair(16u, 16u));
}

TEST_F(MemoryCliTest, RunningOutOfMemoryWhileLoadingNamesTheSceneFileNotTheImage) {
    const std::uint64_t baseline =
        smallestWorkingLimit("render empty.json --backend cpu --threads 1 --width 1 --height 1 -o tiny.png");
    const std::uint64_t fileKiB = writeManyLights(dir_ / "lights.json", 350000) / 1024;
    const RunResult run =
        underLimit(baseline + fileKiB / 2, "render lights.json --backend cpu --threads 1 -o lights.png");
    EXPECT_EQ(run.exitCode, 6) << run.err;
    EXPECT_NE(run.err.find("hexray: error: out of memory: the scene file lights.json (" +
                           std::to_string((fileKiB + 1023) / 1024) + " MiB): loading a scene takes about twice"),
              std::string::npos)
        << run.err;
    EXPECT_EQ(run.err.find("--width"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "lights.png"));
}

TEST_F(MemoryCliTest, RunningOutOfMemoryIsExitCode6AndNamesTheSizeToReduce) {
    // What the process needs before any image memory; a few MiB more cannot hold even one band
    // of a 16384-pixel-wide image.
    const std::uint64_t baseline =
        smallestWorkingLimit("render empty.json --backend cpu --threads 1 --width 1 --height 1 -o tiny.png");
    const RunResult run = underLimit(
        baseline + 4096, "render empty.json --backend cpu --threads 1 --width 16384 --height 64 -o wide.png");
    EXPECT_EQ(run.exitCode, 6) << run.err;
    EXPECT_NE(run.err.find("hexray: error: out of memory"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("--width"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "wide.png"));
    EXPECT_EQ(entriesStartingWith(dir_, "."), std::vector<std::string>{});
}

}  // namespace
}  // namespace hexray
