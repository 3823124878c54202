// The provenance record (image/provenance.h) in what the real executable writes: a render's PNG
// and OpenEXR files, their AOVs, compare's heat map and mask, and merge's output.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"
#include "image/provenance.h"
#include "strip/strip_stamp.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

constexpr const char* kImage = " --width 31 --height 17 --spp 2";

class ProvenanceCliTest : public CliTest {
protected:
    // `hexray --version`'s "0.1.0 (git 9317900a2b4c)", as version and revision.
    std::pair<std::string, std::string> versionAndRevision() const {
        const std::string out = hexray("--version").out;
        const std::string version = out.substr(7, out.find('\n') - 7);
        const std::size_t git = version.find(" (git ");
        return {version.substr(0, git), version.substr(git + 6, version.size() - git - 7)};
    }

    // What a CPU render of lecture-demo.json at kImage records, as `image`.
    Provenance cpuRecord(const std::string& image) const {
        const auto [version, revision] = versionAndRevision();
        const std::string sceneText = readFile(test::sourcePath("scenes/lecture-demo.json"));
        return Provenance{version, revision, image, sceneTextIdentity(sceneText), "cpu", "cpu reference", "f64",
                          2,       31,       17};
    }

    std::string render(const std::string& options) const {
        const RunResult run = hexray("render " + scene("lecture-demo.json") + kImage + " " + options);
        EXPECT_EQ(run.exitCode, 0) << run.err;
        return run.out;
    }
};

TEST_F(ProvenanceCliTest, ARenderedPngRecordsWhatMadeItInTextChunks) {
    render("--backend cpu -o cpu.png");
    EXPECT_EQ(readProvenance(dir_ / "cpu.png"), cpuRecord("render"));
    // Read without hexray's reader: a tEXt chunk, its keyword, a NUL and the text.
    const std::string bytes = readFile(dir_ / "cpu.png");
    EXPECT_NE(bytes.find(std::string("tEXthexray:backend") + '\0' + "cpu"), std::string::npos);
    EXPECT_NE(bytes.find(std::string("tEXthexray:resolution") + '\0' + "31x17"), std::string::npos);
    EXPECT_NE(bytes.find(std::string("tEXthexray:version") + '\0' + versionAndRevision().first), std::string::npos);
}

// docs/provenance.md's Python, which needs no image library, reads what hexray's reader does.
TEST_F(ProvenanceCliTest, TheDocumentedScriptReadsTheRecordOfBothFormats) {
    const std::string doc = test::sourcePath("docs/provenance.md").string();
    const RunResult script = shell("sed -n '/^python3 - IMAGE/,/^EOF$/p' '" + doc + "' | sed '1d;$d' > read.py");
    ASSERT_EQ(script.exitCode, 0) << script.err;
    for (const char* file : {"a.png", "a.exr"}) {
        render("--backend cpu -o " + std::string(file));
        const RunResult run = shell("python3 read.py " + std::string(file) + " | sort");
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const RunResult expected = shell("printf '%s' '" + cpuRecord("render").describe() + "' | sort");
        EXPECT_EQ(run.out, expected.out) << file;
        EXPECT_NE(run.out.find("hexray:backend cpu\n"), std::string::npos) << run.out;
    }
}

TEST_F(ProvenanceCliTest, AGpuRenderRecordsItsDeviceAndThePrecisionUsed) {
    render("--backend gpu --precision auto -o gpu.exr");
    const Provenance record = readProvenance(dir_ / "gpu.exr");
    Provenance expected = cpuRecord("render");
    expected.backend = "gpu";
    expected.precision = record.precision;
    expected.device = record.device;
    EXPECT_EQ(record, expected);
    EXPECT_TRUE(record.precision == "f32" || record.precision == "f64") << record.precision;  // never "auto"
    EXPECT_FALSE(record.device.empty());
    EXPECT_NE(record.device, "cpu reference");
}

TEST_F(ProvenanceCliTest, TheRecordChangesNoPixel) {
    render("--backend cpu -o a.png");
    const Rgb8Image rendered = readPng(dir_ / "a.png");
    writePng(dir_ / "plain.png", rendered);
    EXPECT_TRUE(readProvenance(dir_ / "plain.png").empty());
    EXPECT_EQ(readPng(dir_ / "plain.png").bytes, rendered.bytes);
}

TEST_F(ProvenanceCliTest, AovsRecordTheRenderAndWhichAovTheyAre) {
    render("--backend cpu -o a.png --aov aov");
    EXPECT_EQ(readProvenance(dir_ / "aov" / "depth.exr"), cpuRecord("aov depth"));
    EXPECT_EQ(readProvenance(dir_ / "aov" / "depth.png"), cpuRecord("aov depth preview"));
    EXPECT_EQ(readProvenance(dir_ / "aov" / "normal.png"), cpuRecord("aov normal preview"));
}

TEST_F(ProvenanceCliTest, CompareHeatMapAndMaskRecordBothBackends) {
    const RunResult run =
        hexray("compare " + scene("lecture-demo.json") + kImage + " --precision f32 --diff diff.png --mask mask.png");
    ASSERT_NE(run.exitCode, 2) << run.err;
    for (const auto& [file, image] : {std::pair{"diff.png", "diff heat map"}, std::pair{"mask.png", "mismatch mask"}}) {
        const Provenance record = readProvenance(dir_ / file);
        Provenance expected = cpuRecord(image);
        expected.backend = "gpu vs cpu";
        expected.precision = "f32";
        expected.device = record.device;
        EXPECT_EQ(record, expected) << file;
        EXPECT_FALSE(record.device.empty()) << file;
    }
}

TEST_F(ProvenanceCliTest, AMergedImageRecordsWhatItsPiecesShare) {
    for (const char* extension : {".png", ".exr"}) {
        const std::string ext(extension);
        render("--backend cpu --strip 0/2 -o a" + ext);
        render("--backend cpu --strip 1/2 -o b" + ext);
        const RunResult run = hexray("merge merged" + ext + " a" + ext + " b" + ext);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(readProvenance(dir_ / ("a" + ext)), cpuRecord("render")) << ext;
        EXPECT_EQ(readProvenance(dir_ / ("merged" + ext)), cpuRecord("merged strips")) << ext;
    }
}

}  // namespace
}  // namespace hexray
