// `hexray watch`: renders on start and again after each save (by rename, as editors save), the
// image following the edit; tiered, the tier-up's image is the one the other kernels make; an
// invalid edit is reported and watching goes on; SIGTERM and SIGINT end it with 0 and no
// temporaries. Every wait is for an event (a summary line, a message), its timeout only a guard.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "image/image_io.h"

namespace hexray::test {
namespace {

// The demo scene at 64x48: the sphere covers pixel (28, 24); pixel (40, 21) is background.
std::string demoScene(const std::string& ballColour = "[0.8, 0, 0]", const std::string& extraNodes = "") {
    return R"({"image": {"width": 64, "height": 48},
  "camera": {"position": [0, 60, -120], "yaw": 0, "pitch": 0, "roll": 0, "fov": 90},
  "background": [0, 0, 0], "ambient": [0.15, 0.15, 0.15],
  "lights": [{"position": [30, 100, -70], "color": [1, 1, 1], "intensity": 10000}],
  "shaders": {"floor": {"type": "checker", "color1": [0, 0, 0.8], "color2": [0.2, 0.3, 0.6], "size": 20},
              "ball": {"type": "lambert", "color": )" +
           ballColour + R"(}, "blue": {"type": "lambert", "color": [0, 0, 0.8]}},
  "nodes": [{"geometry": {"type": "plane", "y": 0}, "shader": "floor"},
            {"geometry": {"type": "sphere", "center": [-10, 60, 0], "radius": 10}, "shader": "ball"})" +
           extraNodes + "]}";
}

// A blue sphere right of the red one, covering pixel (40, 21).
const std::string kBlueSphere =
    R"(, {"geometry": {"type": "sphere", "center": [25, 66, 0], "radius": 8}, "shader": "blue"})";

struct Rgb {
    int r, g, b;
};

class WatchCliTest : public CliTest {
protected:
    void TearDown() override {
        if (pid_ > 0) {  // a failed test's watch
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        CliTest::TearDown();
    }

    void startWatch(const std::vector<std::string>& options = {}) {
        writeScene("scene.json", demoScene());
        std::vector<std::string> arguments = {"watch", "scene.json", "-o", "out.png"};
        arguments.insert(arguments.end(), options.begin(), options.end());
        pid_ = start(arguments);
        ASSERT_GT(pid_, 0);
    }

    // Saves the scene as an editor does: another file, renamed over it.
    void saveByRename(const std::string& text) const {
        std::ofstream(dir_ / ".scene.json.swp") << text;
        std::filesystem::rename(dir_ / ".scene.json.swp", dir_ / "scene.json");
    }

    // The summary lines so far, once there are at least `count` (or the process ended).
    std::vector<std::string> waitForLines(std::size_t count) const {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        std::vector<std::string> lines;
        while (std::chrono::steady_clock::now() < deadline) {
            lines.clear();
            std::istringstream out(readFile(dir_ / "stdout.txt"));
            for (std::string line; std::getline(out, line);) {
                lines.push_back(line);
            }
            if (lines.size() >= count || !running()) {
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return lines;
    }

    bool waitForError(const std::string& text) const {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < deadline) {
            if (readFile(dir_ / "stderr.txt").find(text) != std::string::npos) {
                return true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }

    bool running() const { return ::kill(pid_, 0) == 0 && ::waitpid(pid_, nullptr, WNOHANG) == 0; }

    // Sends `signal` and returns the exit code (-1: killed by a signal).
    int stop(int signal) {
        ::kill(pid_, signal);
        int status = 0;
        const pid_t ended = ::waitpid(pid_, &status, 0);
        pid_ = -1;
        return ended > 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    Rgb pixel(std::uint32_t x, std::uint32_t y) const {
        const Rgb8Image image = readPng(dir_ / "out.png");
        const std::size_t at = 3 * (std::size_t(y) * image.width + x);
        return {image.bytes[at], image.bytes[at + 1], image.bytes[at + 2]};
    }

    pid_t pid_ = -1;
};

bool contains(const std::string& line, const std::string& text) {
    return line.find(text) != std::string::npos;
}

TEST_F(WatchCliTest, RendersOnStartThenAfterAValueEditAndAStructuralEdit) {
    startWatch();
    std::vector<std::string> lines = waitForLines(2);
    ASSERT_EQ(lines.size(), 2u) << readFile(dir_ / "stderr.txt");
    EXPECT_TRUE(contains(lines[0], "wrote out.png (64x48) — gpu ") && contains(lines[0], "kernel buffered: "))
        << lines[0];
    EXPECT_TRUE(contains(lines[1], "kernel specialised: ")) << lines[1];
    Rgb ball = pixel(28, 24);
    EXPECT_GT(ball.r, 40);
    EXPECT_EQ(ball.g, 0);
    EXPECT_EQ(ball.b, 0);
    EXPECT_EQ(pixel(40, 21).b, 0);  // background

    saveByRename(demoScene("[0, 0.8, 0]"));
    lines = waitForLines(4);
    ASSERT_EQ(lines.size(), 4u) << readFile(dir_ / "stderr.txt");
    EXPECT_TRUE(contains(lines[2], "kernel buffered: ")) << lines[2];
    EXPECT_TRUE(contains(lines[3], "kernel specialised: ")) << lines[3];
    ball = pixel(28, 24);
    EXPECT_GT(ball.g, 40);
    EXPECT_EQ(ball.r, 0);

    saveByRename(demoScene("[0, 0.8, 0]", kBlueSphere));
    lines = waitForLines(6);
    ASSERT_EQ(lines.size(), 6u) << readFile(dir_ / "stderr.txt");
    EXPECT_TRUE(contains(lines[5], "kernel specialised: ")) << lines[5];
    const Rgb added = pixel(40, 21);
    EXPECT_GT(added.b, 40);
    EXPECT_EQ(added.r, 0);
    EXPECT_EQ(stop(SIGTERM), 0);
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"out.png"});
    EXPECT_EQ(readFile(dir_ / "stderr.txt"), "");
}

TEST_F(WatchCliTest, AnInvalidEditIsReportedWithItsPlaceAndWatchingGoesOn) {
    startWatch({"--kernel", "buffered"});
    ASSERT_EQ(waitForLines(1).size(), 1u) << readFile(dir_ / "stderr.txt");
    std::string broken = demoScene();
    broken.replace(broken.find("\"radius\": 10"), 12, "\"radius\": -3");
    saveByRename(broken);
    ASSERT_TRUE(waitForError("scene.json")) << readFile(dir_ / "stderr.txt");
    const std::string error = readFile(dir_ / "stderr.txt");
    EXPECT_TRUE(contains(error, "hexray: error: ") && contains(error, "nodes[1].geometry.radius")) << error;
    EXPECT_TRUE(running());
    EXPECT_GT(pixel(28, 24).r, 40);  // the last good image stays

    saveByRename(demoScene("[0, 0.8, 0]"));
    ASSERT_EQ(waitForLines(2).size(), 2u) << readFile(dir_ / "stderr.txt");
    EXPECT_GT(pixel(28, 24).g, 40);
    EXPECT_EQ(stop(SIGINT), 0);
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"out.png"});
}

TEST_F(WatchCliTest, TheTierUpsImageIsTheBufferedAndTheDataDrivenKernelsImage) {
    writeScene("scene.json", demoScene("[0.7, 0.5, 0.2]", kBlueSphere));
    const RunResult tiered = hexray("watch scene.json -o tiered.png --frames 2");
    ASSERT_EQ(tiered.exitCode, 0) << tiered.err;
    ASSERT_NE(tiered.out.find("kernel buffered: "), std::string::npos) << tiered.out;
    ASSERT_LT(tiered.out.find("kernel buffered: "), tiered.out.find("kernel specialised: ")) << tiered.out;
    const Rgb8Image specialised = readPng(dir_ / "tiered.png");
    for (const std::string kernel : {"buffered", "data-driven"}) {
        const RunResult run = hexray("watch scene.json -o " + kernel + ".png --frames 1 --kernel " + kernel);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_NE(run.out.find("kernel " + kernel + ": "), std::string::npos) << run.out;
        EXPECT_EQ(readPng(dir_ / (kernel + ".png")).bytes, specialised.bytes) << kernel;
    }
    ASSERT_EQ(hexray("render scene.json -o render.png").exitCode, 0);
    EXPECT_EQ(readPng(dir_ / "render.png").bytes, specialised.bytes);
}

// The stop signals wait for the image being written: the test hook stops watch once a temporary
// exists (the image's, or the kernel cache's), and SIGTERM arrives then.
TEST_F(WatchCliTest, ASignalWhileTheImageIsWrittenEndsWithTheImageWholeAndNoTemporaries) {
    writeScene("scene.json", demoScene());
    pid_ = start({"watch", "scene.json", "-o", "out.png"}, {"HEXRAY_TEST_STOP_AT_TEMPORARY=file"});
    ASSERT_GT(pid_, 0);
    int status = 0;
    ASSERT_EQ(::waitpid(pid_, &status, WUNTRACED), pid_);
    ASSERT_TRUE(WIFSTOPPED(status)) << readFile(dir_ / "stderr.txt");
    ::kill(pid_, SIGTERM);
    do {  // each later temporary stops it again
        ::kill(pid_, SIGCONT);
    } while (::waitpid(pid_, &status, WUNTRACED) == pid_ && WIFSTOPPED(status));
    pid_ = -1;
    ASSERT_TRUE(WIFEXITED(status)) << readFile(dir_ / "stderr.txt");
    EXPECT_EQ(WEXITSTATUS(status), 0) << readFile(dir_ / "stderr.txt");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"out.png"});
    EXPECT_GT(pixel(28, 24).r, 40);
}

TEST_F(WatchCliTest, UsageMistakesAndOutputsItCannotWriteAreRefused) {
    writeScene("scene.json", demoScene());
    const std::vector<std::pair<std::string, std::string>> refused = {
        {"watch", "scene"},
        {"watch scene.json --kernel fast", "--kernel"},
        {"watch scene.json --frames 0", "--frames"},
        {"watch scene.json -o out.exr", "watch writes a PNG file"},
        {"watch missing.json", "missing.json: no such scene file"},
        {"watch scene.json other.json", "other.json"},
    };
    for (const auto& [arguments, message] : refused) {
        const RunResult run = hexray(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.err;
        EXPECT_NE(run.err.find(message), std::string::npos) << arguments << "\n" << run.err;
    }
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

}  // namespace
}  // namespace hexray::test
