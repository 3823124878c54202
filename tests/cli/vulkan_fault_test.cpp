// Vulkan faults through the real executable: each one's message and exit code with
// --backend gpu, the CPU fallback with --backend auto, and no output created or clobbered.
// lavapipe produces "no driver" for real (the loader pointed at a missing ICD); the others come
// from the HEXRAY_INJECT_VULKAN_FAULT test hook (host/vulkan/fault_injection.h), which raises
// each where the real fault would arise.

#include <sys/wait.h>

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

constexpr const char* kNoDriver = "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";

struct Fault {
    const char* name;
    std::string environment;
    const char* extraArguments;
    int exitCode;
    const char* message;  // the reason, as both the error and the auto-fallback note give it
};

void PrintTo(const Fault& fault, std::ostream* out) {
    *out << fault.name;
}

std::string inject(const char* fault) {
    return std::string("HEXRAY_INJECT_VULKAN_FAULT=") + fault;
}

class VulkanFaultTest : public CliTest, public ::testing::WithParamInterface<Fault> {
protected:
    std::string render(const std::string& output, const std::string& backend) const {
        return "render " + scene("lecture-demo.json") + " -o " + output + " --width 64 --height 48 --backend " +
               backend + " " + GetParam().extraArguments;
    }
};

TEST_P(VulkanFaultTest, BackendGpuFailsWithItsMessageAndExitCodeAndNoOutput) {
    const Fault& fault = GetParam();
    std::ofstream(dir_ / "existing.png") << "keep me";
    for (const std::string target : {"new.png", "existing.png"}) {
        const RunResult run = hexray(render(target, "gpu"), fault.environment);
        EXPECT_EQ(run.exitCode, fault.exitCode) << run.err;
        EXPECT_NE(run.err.find(std::string("hexray: error: ") + fault.message), std::string::npos)
            << "expected \"" << fault.message << "\" in:\n"
            << run.err;
        EXPECT_EQ(run.out, "");
    }
    EXPECT_EQ(readFile(dir_ / "existing.png"), "keep me");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"existing.png"});
}

TEST_P(VulkanFaultTest, BackendAutoSaysWhyAndRendersOnTheCpuReference) {
    const Fault& fault = GetParam();
    std::ofstream(dir_ / "auto.png") << "replace me";
    const RunResult run = hexray(render("auto.png", "auto"), fault.environment);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find(std::string("hexray: note: ") + fault.message), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("; rendering on the CPU reference instead\n"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << "one line:\n" << run.err;
    EXPECT_NE(run.out.find("wrote auto.png (64x48) — cpu reference"), std::string::npos) << run.out;

    const RunResult cpu =
        hexray("render " + scene("lecture-demo.json") + " -o cpu.png --width 64 --height 48 --backend cpu");
    ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
    EXPECT_EQ(readPng(dir_ / "auto.png").bytes, readPng(dir_ / "cpu.png").bytes);
    std::vector<std::string> files = createdFiles();
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"auto.png", "cpu.png"}));  // no temporary left behind

    // Under the validation layer the abandoned GPU attempt's teardown is clean: still exit 0.
    const RunResult validated = hexray("--validate " + render("validated.png", "auto"), fault.environment);
    EXPECT_EQ(validated.exitCode, 0) << validated.err;
    EXPECT_EQ(validated.err.find("Vulkan validation"), std::string::npos) << validated.err;
    EXPECT_EQ(readPng(dir_ / "validated.png").bytes, readPng(dir_ / "cpu.png").bytes);
}

INSTANTIATE_TEST_SUITE_P(
    Faults, VulkanFaultTest,
    ::testing::Values(Fault{"NoDriver", kNoDriver, "", 3, "no Vulkan driver found"},
                      Fault{"NoComputeQueue", inject("no-compute-queue"), "", 3,
                            "no Vulkan device has a compute queue (devices: 0: llvmpipe"},
                      Fault{"NoFloat64", inject("no-float64"), "--precision f64", 3,
                            "--precision f64 needs shaderFloat64, which llvmpipe"},
                      Fault{"DeviceLost", inject("device-lost"), "", 7,
                            "the Vulkan device was lost while rendering on llvmpipe"},
                      Fault{"DeviceHang", inject("device-hang"), "", 7,
                            "the Vulkan device timed out: a render did not finish within 60 s on llvmpipe"},
                      Fault{"OutOfDeviceMemory", inject("out-of-device-memory"), "", 8,
                            "out of memory while allocating a 1 KiB buffer (ErrorOutOfDeviceMemory)"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(CliTest, WithoutFloat64AutoPrecisionStaysOnTheGpuInF32) {
    // Only an explicit f64 request needs float64: auto picks f32 and no fallback happens.
    const RunResult run =
        hexray("render " + scene("lecture-demo.json") + " -o a.png --width 64 --height 48", inject("no-float64"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("gpu f32"), std::string::npos) << run.out;
    EXPECT_EQ(run.err, "");
}

TEST_F(CliTest, AnUnknownDeviceIsNotFallenBackFrom) {
    // A typo in --device is the user's mistake to fix, not a reason to render elsewhere.
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o x.png --backend auto --device nope");
    EXPECT_EQ(run.exitCode, 3) << run.err;
    EXPECT_NE(run.err.find("no Vulkan device matches --device nope"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("note:"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, CompareHasNoFallbackAndReportsTheFaultsExitCode) {
    const std::string compare = "compare " + scene("lecture-demo.json") + " --width 32 --height 24";
    RunResult run = hexray(compare, inject("device-lost"));
    EXPECT_EQ(run.exitCode, 7) << run.err;
    EXPECT_NE(run.err.find("hexray: error: the Vulkan device was lost"), std::string::npos) << run.err;
    run = hexray(compare, inject("out-of-device-memory"));
    EXPECT_EQ(run.exitCode, 8) << run.err;
    EXPECT_NE(run.err.find("hexray: error: out of memory while allocating"), std::string::npos) << run.err;
    run = hexray(compare, kNoDriver);
    EXPECT_EQ(run.exitCode, 3) << run.err;
}

TEST_F(CliTest, AnUnknownInjectedFaultIsAnErrorNotIgnored) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o x.png", inject("device-lots"));
    EXPECT_EQ(run.exitCode, 6) << run.err;
    EXPECT_NE(run.err.find("HEXRAY_INJECT_VULKAN_FAULT: unknown fault \"device-lots\""), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, TwoRendersAtOnceBothFinishWithTheSequentialImage) {
    const std::string render = "'" + test::hexrayExecutable() + "' render " + scene("spheres-and-lights.json") +
                               " --backend gpu --width 800 --height 600 --spp 2";
    const RunResult sequential = hexray("render " + scene("spheres-and-lights.json") +
                                        " --backend gpu --width 800 --height 600 --spp 2 -o sequential.png");
    ASSERT_EQ(sequential.exitCode, 0) << sequential.err;
    const std::string command = "cd '" + dir_.string() + "' && (" + render + " -o a.png >a.log 2>&1 & a=$!; " + render +
                                " -o b.png >b.log 2>&1 & b=$!; wait $a; ra=$?; wait $b; rb=$?; " +
                                "exit $((ra * 16 + rb)))";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "exit codes a*16+b; logs:\n"
                                      << readFile(dir_ / "a.log") << readFile(dir_ / "b.log");
    const Rgb8Image expected = readPng(dir_ / "sequential.png");
    EXPECT_EQ(readPng(dir_ / "a.png").bytes, expected.bytes);
    EXPECT_EQ(readPng(dir_ / "b.png").bytes, expected.bytes);
}

}  // namespace
}  // namespace hexray
