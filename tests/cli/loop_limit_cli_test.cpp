// lavapipe ends a shader's loops after 65535 passes in all (gpu/loop_budget.h). A scene that light
// batches keep within it agrees with the reference; one that a single sample with a single light
// takes past it is refused with exit code 3 and a message naming --backend cpu, and `--backend
// auto` renders it on the CPU reference instead, with a note. Tracing a pixel, one invocation, is
// refused the same way.

#include <fstream>
#include <string>

#include "cli_fixture.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

class LoopLimitCliTest : public test::CliTest {
protected:
    // A floor seen from above, filling a 16x12 image; `planes` - 1 more planes below it, and
    // `lights` lights over it whose terms sum to a mid grey.
    fs::path writeFloor(const std::string& name, std::size_t planes, std::size_t lights) const {
        const fs::path path = dir_ / name;
        std::ofstream out(path);
        out << R"({"image": {"width": 16, "height": 12}, )"
            << R"("camera": {"position": [0, 3, 0], "pitch": -60, "fov": 70}, )"
            << R"("shaders": {"grey": {"type": "lambert", "color": [0.5, 0.5, 0.5]}}, "nodes": [)";
        for (std::size_t i = 0; i < planes; ++i) {
            out << (i ? "," : "") << R"({"geometry": {"type": "plane", "y": -)" << i << R"(}, "shader": "grey"})";
        }
        // 40 x 40 lights a layer at heights 8 to 12: 2 pi P / A of irradiance in all, about 0.5.
        const double intensity = 0.5 * 1600.0 / (2.0 * 3.14159265 * double(lights));
        out << R"(], "lights": [)";
        for (std::size_t i = 0; i < lights; ++i) {
            out << (i ? "," : "") << R"({"position": [)" << double(i % 40) - 19.5 << ","
                << 8.0 + double(i / 1600) * 0.25 << "," << double(i / 40 % 40) - 9.5 << R"(], "intensity": )"
                << intensity << "}";
        }
        out << "]}";
        return path;
    }
};

TEST_F(LoopLimitCliTest, AFloorUnder25000LightsRendersInLightBatchesAndAgreesWithTheReference) {
    writeFloor("lights.json", 1, 25000);
    const test::RunResult run = hexray("compare lights.json");
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("PASS"), std::string::npos) << run.out;
    const test::RunResult render = hexray("render lights.json --backend gpu -o lights.png");
    EXPECT_EQ(render.exitCode, 0) << render.err;
    EXPECT_NE(render.out.find("2 batches of lights a sample (the device's loop limit)"), std::string::npos)
        << render.out;
}

// 33000 planes: the camera ray's loop over them and one light's shadow test, 66006 passes.
TEST_F(LoopLimitCliTest, AScenePastTheLimitForOneSampleAndOneLightIsRefusedOnTheGpu) {
    writeFloor("planes.json", 33000, 1);
    const test::RunResult run = hexray("render planes.json --backend gpu -o planes.png");
    EXPECT_EQ(run.exitCode, 3) << run.err;
    EXPECT_NE(run.err.find("65535"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("use --backend cpu"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(LoopLimitCliTest, AScenePastTheLimitForOneSampleAndOneLightFallsBackToTheCpuWithAuto) {
    writeFloor("planes.json", 33000, 1);
    const test::RunResult run = hexray("render planes.json -o planes.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("note:"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("rendering on the CPU reference instead"), std::string::npos) << run.err;
    EXPECT_NE(run.out.find("cpu reference"), std::string::npos) << run.out;
    EXPECT_TRUE(fs::exists(dir_ / "planes.png"));
}

// The image renders in light batches; the trace of a pixel cannot be split.
TEST_F(LoopLimitCliTest, TracingAPixelPastTheLimitIsRefused) {
    writeFloor("lights.json", 1, 25000);
    const test::RunResult run = hexray("pixel lights.json 8 6 --backend gpu");
    EXPECT_EQ(run.exitCode, 3) << run.err;
    EXPECT_NE(run.err.find("tracing a pixel"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("use --backend cpu"), std::string::npos) << run.err;
    EXPECT_EQ(hexray("pixel lights.json 8 6 --backend cpu").exitCode, 0);
}

}  // namespace
}  // namespace hexray
