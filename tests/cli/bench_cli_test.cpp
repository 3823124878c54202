// `hexray bench`'s data: the CSV and the --json document, read as a script would, on a bench small
// enough to run in seconds. Nothing here depends on how fast the machine is: only on what the
// rows are and how their figures relate.

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
using Rows = std::vector<std::vector<std::string>>;

// More spheres than a generated kernel holds (SMALL_SCENE_CAPACITY): the data-driven kernel,
// which culling cannot apply to, so a culled and a whole configuration run the same kernel.
std::string manySpheresScene() {
    std::ostringstream nodes;
    for (int i = 0; i < 40; ++i) {
        nodes << (i ? ", " : "") << R"({"geometry": {"type": "sphere", "center": [)" << (i % 8) * 12 - 42 << ", "
              << 50 + (i / 8) * 6 << R"(, 0], "radius": 3}, "shader": "ball"})";
    }
    return R"({
  "image": {"width": 16, "height": 12},
  "camera": {"position": [0, 60, -120], "fov": 90},
  "ambient": [0.15, 0.15, 0.15],
  "lights": [{"position": [30, 100, -70], "intensity": 10000}],
  "shaders": {"ball": {"type": "lambert", "color": [0.8, 0, 0]}},
  "nodes": [)" +
           nodes.str() + "]}";
}

constexpr const char* kSmallBench = " --width 16 --height 12 --rounds 1 --samples 1 --reference-samples 1";

Rows csvRows(const std::string& text) {
    Rows rows;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) {
            fields.push_back(cell);
        }
        if (!line.empty() && line.back() == ',') {
            fields.emplace_back();
        }
        rows.push_back(fields);
    }
    return rows;
}

std::size_t columnOf(const Rows& rows, const std::string& column) {
    const auto& header = rows.at(0);
    return std::size_t(std::find(header.begin(), header.end(), column) - header.begin());
}

std::string field(const Rows& rows, std::size_t row, const std::string& column) {
    const std::size_t at = columnOf(rows, column);
    EXPECT_LT(at, rows.at(0).size()) << column;
    return at < rows.at(row).size() ? rows.at(row).at(at) : "(no column " + column + ")";
}

std::optional<double> number(const std::string& text) {
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// What a row is: with the scene, every dimension of the configuration measured.
const std::vector<std::string> kKeyColumns = {
    "scene",           "spheres",        "width",         "height",       "backend", "kernel",
    "precision_asked", "precision_used", "culling_asked", "culling_used", "spp"};
// The columns that hold words; every other holds a number or nothing.
const std::set<std::string> kTextColumns = {"scene",          "backend",       "kernel",       "precision_asked",
                                            "precision_used", "culling_asked", "culling_used", "auto_pick"};

class BenchCliTest : public CliTest {
protected:
    Rows benchCsv(const std::string& arguments) {
        const RunResult run = hexray("bench " + arguments + kSmallBench + " --csv b.csv");
        EXPECT_EQ(run.exitCode, 0) << run.err;
        text_ = readFile(dir_ / "b.csv");
        return csvRows(text_);
    }
    std::string text_;
};

TEST_F(BenchCliTest, EveryCsvRowIsTellApartByItsConfiguration) {
    writeScene("many.json", manySpheresScene());
    const Rows rows = benchCsv("many.json");
    SCOPED_TRACE(text_);
    ASSERT_GT(rows.size(), 4u);
    std::vector<std::size_t> key;
    for (const std::string& column : kKeyColumns) {
        EXPECT_LT(columnOf(rows, column), rows[0].size()) << "no column " << column;
        if (columnOf(rows, column) < rows[0].size()) {
            key.push_back(columnOf(rows, column));
        }
    }
    std::set<std::vector<std::string>> seen;
    for (std::size_t row = 1; row < rows.size(); ++row) {
        ASSERT_EQ(rows[row].size(), rows[0].size()) << "row " << row;
        std::vector<std::string> values;
        for (const std::size_t column : key) {
            values.push_back(rows[row][column]);
        }
        EXPECT_TRUE(seen.insert(values).second) << "row " << row << " repeats another's configuration";
    }
}

TEST_F(BenchCliTest, CsvNumericColumnsHoldNumbersOrNothing) {
    writeScene("many.json", manySpheresScene());
    const Rows rows = benchCsv("many.json --spheres 3");
    SCOPED_TRACE(text_);
    for (std::size_t row = 1; row < rows.size(); ++row) {
        for (std::size_t column = 0; column < rows[0].size() && column < rows[row].size(); ++column) {
            const std::string& cell = rows[row][column];
            if (!kTextColumns.contains(rows[0][column]) && !cell.empty()) {
                EXPECT_TRUE(number(cell)) << rows[0][column] << " of row " << row << ": '" << cell << "'";
            }
        }
    }
}

TEST_F(BenchCliTest, CsvNumbersKeepFullPrecisionAndNotApplicableIsEmpty) {
    const Rows rows = benchCsv(scene("lecture-demo.json"));
    SCOPED_TRACE(text_);
    for (std::size_t row = 1; row < rows.size(); ++row) {
        const std::string backend = field(rows, row, "backend");
        // Mpix/s is computed from the render's milliseconds: written in full, one gives the other
        // back to the last bit.
        const double ms = number(field(rows, row, "median_render_ms")).value_or(NAN);
        EXPECT_EQ(number(field(rows, row, "median_mpix_s")), 16.0 * 12.0 * 1e-3 / ms) << backend;
        EXPECT_GT(number(field(rows, row, "median_mpix_s")).value_or(0), 0.0) << backend;
        const bool gpu = backend.starts_with("lavapipe");
        EXPECT_EQ(field(rows, row, "plan_ms").empty(), !gpu) << backend;
        EXPECT_EQ(field(rows, row, "upload_ms").empty(), !gpu) << backend;
        EXPECT_EQ(field(rows, row, "culling_asked").empty(), backend != "lavapipe") << backend;
    }
    EXPECT_EQ(text_.find("\xe2\x80\x93"), std::string::npos) << "a dash stands for a value";
}

TEST_F(BenchCliTest, JsonHasEveryConfigurationAndAgreesWithTheCsv) {
    writeScene("many.json", manySpheresScene());
    const RunResult run = hexray("bench many.json --spheres 2 --max-frame-seconds 1e9" + std::string(kSmallBench) +
                                 " --csv b.csv --json b.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const RunResult valid = validateJson("b.json");
    EXPECT_EQ(valid.exitCode, 0) << valid.out << valid.err;
    EXPECT_EQ(valid.out, "");
    const nlohmann::json document = nlohmann::json::parse(readFile(dir_ / "b.json"));
    EXPECT_EQ(document["schema"], "hexray-bench/1");
    EXPECT_EQ(document["exit"]["code"], 0);
    EXPECT_EQ(document["exit"]["name"], "success");
    EXPECT_GT(document["timings_ms"]["startup"].get<double>(), 0.0);
    EXPECT_GE(document["timings_ms"]["wall"].get<double>(), document["timings_ms"]["startup"].get<double>());
    EXPECT_FALSE(document["device"]["name"].get<std::string>().empty());
    const Rows rows = csvRows(readFile(dir_ / "b.csv"));
    ASSERT_EQ(document["scenes"].size(), 2u);  // many, and the curve's 2-sphere scene
    EXPECT_EQ(document["scenes"][1]["spheres"], 2);
    std::size_t row = 1;
    int identicalRows = 0;
    for (const nlohmann::json& scene : document["scenes"]) {
        for (const nlohmann::json& configuration : scene["configurations"]) {
            ASSERT_LT(row, rows.size());
            SCOPED_TRACE(configuration.dump());
            EXPECT_EQ(field(rows, row, "scene"), scene["name"]);
            EXPECT_EQ(field(rows, row, "backend"), configuration["backend"]);
            EXPECT_EQ(field(rows, row, "precision_used"), configuration["precision"]["used"]);
            // One run's figures, written in full both ways: the same numbers.
            EXPECT_EQ(number(field(rows, row, "median_mpix_s")), configuration["speed"]["median_mpix_s"].get<double>());
            EXPECT_EQ(number(field(rows, row, "precision_rmse_levels")),
                      configuration["error"]["precision"]["rmse_levels"].get<double>());
            // Mean FLIP against the same reference, every pixel: a share, and 0 for the reference's own
            // render, which is the reference (the CPU renderer is deterministic).
            ASSERT_TRUE(configuration["error"]["flip_mean"].is_number());
            const double flip = configuration["error"]["flip_mean"].get<double>();
            EXPECT_GE(flip, 0.0);
            EXPECT_LE(flip, 1.0);
            EXPECT_EQ(number(field(rows, row, "precision_flip_mean")), flip);
            if (configuration["backend"] == "cpu-reference") {
                EXPECT_EQ(flip, 0.0);
                ++identicalRows;
            }
            const bool culled = configuration["culling"]["used"].is_boolean() && configuration["culling"]["used"];
            EXPECT_EQ(field(rows, row, "culling_used") == "on", culled);
            if (configuration["backend"] == "lavapipe") {
                // Past SMALL_SCENE_CAPACITY the data-driven kernel runs, which culling does not apply to.
                EXPECT_EQ(configuration["kernel"] == "generated", scene["name"] == "random-spheres");
                EXPECT_FALSE(culled && scene["name"] == "many");
            }
            ++row;
        }
    }
    EXPECT_EQ(row, rows.size());
    EXPECT_EQ(identicalRows, 2);  // the CPU reference's row in each scene
}

TEST_F(BenchCliTest, JsonToStandardOutputLeavesTheTablesOnStandardError) {
    const RunResult run = hexray("bench " + scene("lecture-demo.json") + kSmallBench + " --json -");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json document = nlohmann::json::parse(run.out);
    EXPECT_EQ(document["command"], "bench");
    EXPECT_NE(run.err.find("| scene | resolution | backend |"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("| mean FLIP vs CPU ref, same spp |"), std::string::npos) << run.err;
    std::ofstream(dir_ / "out.json") << run.out;
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
}

// The (backend, precision used, culling asked) of every row.
std::multiset<std::string> rowKinds(const Rows& rows) {
    std::multiset<std::string> kinds;
    for (std::size_t row = 1; row < rows.size(); ++row) {
        kinds.insert(field(rows, row, "scene") + " " + field(rows, row, "backend") + " " +
                     field(rows, row, "precision_used") + " " + field(rows, row, "culling_asked"));
    }
    return kinds;
}

TEST_F(BenchCliTest, BackendsChoosesTheRowsOfEveryScene) {
    const Rows rows =
        benchCsv(scene("lecture-demo.json") + " --spheres 2 --max-frame-seconds 1e9 --backends gpu-f32,cpu");
    SCOPED_TRACE(text_);
    EXPECT_EQ(rowKinds(rows),
              (std::multiset<std::string>{"lecture-demo lavapipe f32 off", "lecture-demo lavapipe f32 on",
                                          "lecture-demo cpu-reference f64 ", "random-spheres lavapipe f32 off",
                                          "random-spheres cpu-reference f64 "}));
}

TEST_F(BenchCliTest, BackendsWithoutTheCpuStillJudgesTheImagesButNotTheirSampling) {
    const RunResult run = hexray("bench " + scene("lecture-demo.json") + kSmallBench +
                                 " --backends gpu-f32-naive,gpu-f32 --csv b.csv --json b.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    text_ = readFile(dir_ / "b.csv");
    const Rows rows = csvRows(text_);
    SCOPED_TRACE(text_);
    EXPECT_EQ(rowKinds(rows),
              (std::multiset<std::string>{"lecture-demo lavapipe f32-naive off", "lecture-demo lavapipe f32 off",
                                          "lecture-demo lavapipe f32 on"}));
    for (std::size_t row = 1; row < rows.size(); ++row) {
        EXPECT_EQ(field(rows, row, "sampling_rmse_levels"), "");  // no converged reference
        EXPECT_FALSE(field(rows, row, "precision_rmse_levels").empty());
        EXPECT_FALSE(field(rows, row, "topology_mismatches").empty());
    }
    EXPECT_NE(run.out.find("Sampling error: not measured, as --backends leaves out cpu"), std::string::npos) << run.out;
    const nlohmann::json document = nlohmann::json::parse(readFile(dir_ / "b.json"));
    EXPECT_EQ(document["settings"]["backends"], nlohmann::json({"gpu-f32-naive", "gpu-f32"}));
    EXPECT_EQ(validateJson("b.json").exitCode, 0);
}

TEST_F(BenchCliTest, TheDefaultBackendsAreRecorded) {
    const RunResult run = hexray("bench " + scene("lecture-demo.json") + kSmallBench + " --json b.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json document = nlohmann::json::parse(readFile(dir_ / "b.json"));
    EXPECT_EQ(document["settings"]["backends"], nlohmann::json({"gpu", "hand-written", "cpu", "embree"}));
}

#ifdef HEXRAY_WITH_EMBREE
// Embree's rows: the yardstick at its best by default, the rows that shade in double on request,
// each named for how it traces and shades; all agree with the reference on every unambiguous pixel.
TEST_F(BenchCliTest, BackendsChoosesEmbreesRowsByName) {
    const Rows rows = benchCsv(scene("lecture-demo.json") + " --backends embree,embree-f64-packets,embree-f64-single");
    SCOPED_TRACE(text_);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_TRUE(field(rows, 1, "backend").ends_with("-ray packets (f32 shading)")) << field(rows, 1, "backend");
    EXPECT_EQ(field(rows, 2, "backend"), "embree 8-ray packets (f64 shading)");
    EXPECT_EQ(field(rows, 3, "backend"), "embree single rays (f64 shading)");
    for (std::size_t row = 1; row < rows.size(); ++row) {
        EXPECT_EQ(field(rows, row, "topology_mismatches"), "0") << field(rows, row, "backend");
    }
}
#endif

TEST_F(BenchCliTest, AnUnknownBackendIsAUsageErrorThatSuggestsTheNearestName) {
    const RunResult run =
        hexray("bench " + scene("lecture-demo.json") + kSmallBench + " --backends gpu,embre --csv b.csv");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("--backends: embre not in {gpu,"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("did you mean embree?"), std::string::npos) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(BenchCliTest, AFailedBenchStillWritesItsDocument) {
    writeScene("bad.json", "{\"image\": ");
    const RunResult run = hexray("bench bad.json" + std::string(kSmallBench) + " --json b.json");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    const RunResult valid = validateJson("b.json");
    EXPECT_EQ(valid.exitCode, 0) << valid.out;
    const nlohmann::json document = nlohmann::json::parse(readFile(dir_ / "b.json"));
    EXPECT_EQ(document["exit"]["code"], 2);
    EXPECT_EQ(document["exit"]["name"], "bad_input");
    ASSERT_FALSE(document["exit"]["messages"].empty());
    EXPECT_NE(document["exit"]["messages"][0].get<std::string>().find("bad.json"), std::string::npos);
    EXPECT_TRUE(document["scenes"].empty());
}

}  // namespace
}  // namespace hexray
