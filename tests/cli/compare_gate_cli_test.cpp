// compare as a CI gate: the expectations file beside the scenes (hexray-expectations.json), the
// count line, and the results as JSON and JUnit XML, each checked against its schema.

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

class CompareGateCliTest : public test::CliTest {
protected:
    // A scene tree of copies of shipped scenes (names under scenes/), with `expectations` as its
    // hexray-expectations.json when not empty.
    void makeTree(const std::vector<std::string>& scenes, const std::string& expectations) const {
        fs::create_directories(dir_ / "tree");
        for (const std::string& name : scenes) {
            fs::copy_file(test::sourcePath("scenes/" + name), dir_ / "tree" / fs::path(name).filename());
        }
        if (!expectations.empty()) {
            std::ofstream(dir_ / "tree" / "hexray-expectations.json") << expectations;
        }
    }

    Json readJson(const std::string& name) const {
        std::ifstream in(dir_ / name);
        return Json::parse(in);
    }

    test::RunResult validateJunit(const std::string& document) const {
        return shell("/usr/bin/python3 '" + test::sourcePath("tests/cli/validate_junit.py").string() + "' '" +
                     test::sourcePath("tests/cli/junit.xsd").string() + "' '" + document + "'");
    }

    static std::string lastLine(const std::string& text) {
        const std::size_t end = text.find_last_not_of('\n');
        const std::size_t start = text.rfind('\n', end);
        return text.substr(start == std::string::npos ? 0 : start + 1,
                           end - (start == std::string::npos ? 0 : start + 1) + 1);
    }
};

// light-on-plane is near-tied on purpose (27.9 % of its pixels at every precision); camera-inside-sphere
// passes at 0 %.
constexpr const char* kExpectLightOnPlaneAmbiguous = R"({"schema": "hexray-expectations/1", "expectations": [
    {"scenes": ["light-on-plane.json"], "expect": "too_ambiguous", "why": "a light in the floor"}]})";

TEST_F(CompareGateCliTest, TheShippedScenesPassWithTheirExpectations) {
    const test::RunResult run = hexray("compare --all " + scene("") + " --json out.json --junit out.xml");
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_EQ(lastLine(run.out).rfind("PASS: ", 0), 0u) << lastLine(run.out);
    EXPECT_NE(run.out.find("| hard/light-on-plane | f32 | ✓ |"), std::string::npos) << run.out;
    const Json document = readJson("out.json");
    EXPECT_EQ(document["summary"]["failed"], 0);
    EXPECT_GT(document["summary"]["expected"].get<int>(), 0);
    EXPECT_GT(document["summary"]["passed"].get<int>(), 0);
    for (const Json& result : document["results"]) {
        if (result["name"] == "hard/light-on-plane" && result["precision"] != "f32-naive") {
            EXPECT_EQ(result["outcome"], "expected") << result.dump();
            EXPECT_FALSE(result["checks"]["ambiguous_share"].get<bool>());
        }
    }
    const test::RunResult schema = validateJson("out.json");
    EXPECT_EQ(schema.exitCode, 0) << schema.out << schema.err;
    const test::RunResult junit = validateJunit("out.xml");
    EXPECT_EQ(junit.exitCode, 0) << junit.out << junit.err;
}

TEST_F(CompareGateCliTest, ANearTiedSceneFailsWithoutItsExpectationAndIsExpectedWithIt) {
    makeTree({"hard/light-on-plane.json"}, "");
    const test::RunResult without = hexray("compare tree --precision f32");
    EXPECT_EQ(without.exitCode, 1) << without.out << without.err;
    EXPECT_EQ(lastLine(without.out), "FAIL: 0 passed, 0 expected, 1 failed");

    std::ofstream(dir_ / "tree" / "hexray-expectations.json") << kExpectLightOnPlaneAmbiguous;
    const test::RunResult with = hexray("compare tree --precision f32");
    EXPECT_EQ(with.exitCode, 0) << with.out << with.err;
    EXPECT_EQ(lastLine(with.out), "PASS: 0 passed, 1 expected, 0 failed");
    EXPECT_NE(with.out.find("too ambiguous, as "), std::string::npos) << with.out;
    EXPECT_NE(with.out.find("a light in the floor"), std::string::npos) << with.out;

    const test::RunResult ignored = hexray("compare tree --precision f32 --no-expectations");
    EXPECT_EQ(ignored.exitCode, 1) << ignored.out << ignored.err;
}

// Strict, as pytest's strict xfail: an expected failure that passes fails the gate.
TEST_F(CompareGateCliTest, AnExpectationThatNoLongerHoldsFailsTheGate) {
    makeTree({"hard/camera-inside-sphere.json"}, R"({"schema": "hexray-expectations/1", "expectations": [
        {"scenes": ["camera-*.json"], "expect": "too_ambiguous", "why": "stale"}]})");
    const test::RunResult run = hexray("compare tree tree --json out.json --junit out.xml");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("FAIL (passed; expected too_ambiguous)"), std::string::npos) << run.out;
    EXPECT_EQ(lastLine(run.out), "FAIL: 0 passed, 0 expected, 2 failed");
    const Json document = readJson("out.json");
    EXPECT_EQ(document["exit"]["code"], 1);
    EXPECT_EQ(document["exit"]["name"], "tolerance_exceeded");
    EXPECT_EQ(document["results"][0]["outcome"], "failed");
    EXPECT_NE(document["results"][0]["reason"].get<std::string>().find("expects it too ambiguous"), std::string::npos);
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    const test::RunResult junit = validateJunit("out.xml");
    EXPECT_EQ(junit.exitCode, 0) << junit.out;
    const std::string xml = test::readFile(dir_ / "out.xml");
    EXPECT_NE(xml.find(R"(failures="2")"), std::string::npos) << xml;
    EXPECT_NE(xml.find("<failure message=\"passed, but "), std::string::npos) << xml;
    EXPECT_NE(xml.find("topology mismatches 0 (max 0)"), std::string::npos) << xml;  // the metrics travel along
}

// The file's tolerance applies where it matches; a tolerance given on the command line wins over it.
TEST_F(CompareGateCliTest, CommandLineTolerancesWinOverTheFile) {
    makeTree({"hard/light-on-plane.json"}, R"({"schema": "hexray-expectations/1", "expectations": [
        {"scenes": ["*.json"], "tolerance": {"max_ambiguous_percent": 50}}]})");
    const test::RunResult file = hexray("compare tree --precision f32 --json out.json");
    EXPECT_EQ(file.exitCode, 0) << file.out << file.err;
    EXPECT_EQ(readJson("out.json")["results"][0]["tolerance"]["max_ambiguous_percent"], 50.0);
    const test::RunResult commandLine = hexray("compare tree --precision f32 --max-ambiguous 5");
    EXPECT_EQ(commandLine.exitCode, 1) << commandLine.out << commandLine.err;
    EXPECT_NE(commandLine.out.find("<= 5.0000% EXCEEDED"), std::string::npos) << commandLine.out;
}

TEST_F(CompareGateCliTest, ABadExpectationsFileIsRefusedNamingTheFileAndThePlace) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"schema": "hexray-expectations/1", "expectations": [{"sceens": ["*.json"]}]})",
         "hexray-expectations.json: expectations[0].sceens: unknown key"},
        {R"({"schema": "hexray-expectations/1", "expectations": [{"scenes": ["renamed.json"]}]})",
         "hexray-expectations.json: expectations[0].scenes[0]: matches no scene file"},
        {R"({"schema": "hexray-expectations/1", "expectations": [{"scenes": ["*.json"], "expect": "fail"}]})",
         "hexray-expectations.json: expectations[0].why: missing required field"},
        {R"({"schema": "hexray-expectations/1", "expectations": [{"scenes": ["*.json"], "expect": "flaky", "why": "x"}]})",
         "expectations[0].expect: unknown value \"flaky\""},
        {R"({"schema": "hexray-expectations/2", "expectations": []})", "unknown schema"},
        {R"({"schema": "hexray-expectations/1", "expectations": [)", "not valid JSON"},
    };
    makeTree({"hard/light-on-plane.json"}, "");
    for (const auto& [text, message] : cases) {
        std::ofstream(dir_ / "tree" / "hexray-expectations.json") << text;
        const test::RunResult run = hexray("compare tree --json out.json");
        EXPECT_EQ(run.exitCode, 2) << text << run.out << run.err;
        EXPECT_NE(run.err.find(message), std::string::npos) << text << "\n" << run.err;
        EXPECT_EQ(run.out.find("| light-on-plane"), std::string::npos) << "nothing compared: " << run.out;
        const Json document = readJson("out.json");  // the failure has its document too
        EXPECT_EQ(document["exit"]["name"], "bad_input");
        EXPECT_NE(document["exit"]["messages"][0].get<std::string>().find(message), std::string::npos);
        EXPECT_EQ(validateJson("out.json").exitCode, 0);
    }
}

TEST_F(CompareGateCliTest, JsonOnStandardOutputLeavesTheTableToStandardError) {
    const test::RunResult run = hexray("compare " + scene("constant-debug.json") + " --width 32 --height 24 --json -");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const Json document = Json::parse(run.out);  // nothing else on standard output
    EXPECT_EQ(document["schema"], "hexray-compare/1");
    EXPECT_EQ(document["results"][0]["width"], 32);
    EXPECT_EQ(document["results"][0]["topology"]["pixels"], 32 * 24);
    EXPECT_EQ(document["summary"]["passed"], 1);
    EXPECT_NE(run.err.find("PASS: 1 passed, 0 expected, 0 failed"), std::string::npos) << run.err;
}

TEST_F(CompareGateCliTest, AnUnloadableSceneIsAFailedResultAndAJunitError) {
    makeTree({"constant-debug.json"}, "");
    std::ofstream(dir_ / "tree" / "broken.json") << "{";
    const test::RunResult run = hexray("compare tree --width 32 --height 24 --json out.json --junit out.xml");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    const Json document = readJson("out.json");
    EXPECT_EQ(document["summary"]["failed"], 1);
    EXPECT_EQ(document["summary"]["passed"], 1);
    EXPECT_EQ(document["results"][0]["name"], "broken");
    EXPECT_TRUE(document["results"][0].contains("error"));
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    EXPECT_EQ(validateJunit("out.xml").exitCode, 0);
    EXPECT_NE(test::readFile(dir_ / "out.xml").find(R"(errors="1")"), std::string::npos);
}

// Mean FLIP beside RMSE: 0 for identical outputs, large where the textbook formulation draws
// another picture (topology mismatches on a far checker floor).
TEST_F(CompareGateCliTest, MeanFlipIsReportedBesideRmse) {
    const test::RunResult same =
        hexray("compare " + scene("constant-debug.json") + " --width 32 --height 24 --json a.json");
    ASSERT_EQ(same.exitCode, 0) << same.out << same.err;
    EXPECT_NE(same.out.find("mean LDR-FLIP of the 8-bit outputs"), std::string::npos) << same.out;
    const Json identical = readJson("a.json")["results"][0];
    ASSERT_EQ(identical["encoded"]["max_abs"], 0.0);
    EXPECT_EQ(identical["flip_mean"], 0.0);
    const test::RunResult naive =
        hexray("compare " + scene("hard/checker-far-1e7.json") + " --precision f32-naive --json b.json --junit b.xml");
    EXPECT_EQ(naive.exitCode, 1) << naive.out << naive.err;
    const Json different = readJson("b.json")["results"][0];
    EXPECT_GT(different["topology"]["mismatches"].get<int>(), 0);
    EXPECT_GT(different["flip_mean"].get<double>(), 0.01);
    EXPECT_LE(different["flip_mean"].get<double>(), 1.0);
    EXPECT_NE(test::readFile(dir_ / "b.xml").find("mean FLIP 0."), std::string::npos);
    EXPECT_EQ(validateJson("b.json").exitCode, 0);
}

}  // namespace
}  // namespace hexray
