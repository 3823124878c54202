#include "cli/compare_expectations.h"

#include <fnmatch.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/scene_files.h"
#include "scene/json_reader.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::pair<const char*, Expected> kExpectedNames[] = {
    {"pass", Expected::Pass}, {"too_ambiguous", Expected::TooAmbiguous}, {"fail", Expected::Fail}};

Json parseFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw SceneError(printable(path) + ": cannot read the expectations file");
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
        return Json::parse(text.str());
    } catch (const Json::parse_error& error) {
        throw SceneError(printable(path) + ": not valid JSON: " + error.what());
    }
}

// A scene's path relative to the expectations file's directory, as the globs spell it.
std::string relativeScenePath(const fs::path& directory, const std::string& scenePath) {
    std::error_code error;
    const fs::path absolute = fs::weakly_canonical(fs::absolute(scenePath), error);
    return fs::relative(error ? fs::absolute(scenePath) : absolute, directory).generic_string();
}

bool matches(const std::vector<std::string>& patterns, const std::string& relative) {
    return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& pattern) {
        return ::fnmatch(pattern.c_str(), relative.c_str(), FNM_PATHNAME) == 0;
    });
}

ToleranceChanges readTolerance(const JsonReader& tolerance) {
    tolerance.rejectUnknownKeys(
        {"max_topology_mismatches", "max_bad_pixels_percent", "max_rmse_levels", "max_ambiguous_percent"});
    ToleranceChanges changes;
    if (const auto value = tolerance.find("max_topology_mismatches")) {
        changes.maxTopologyMismatches = std::uint64_t(value->integer(0, std::numeric_limits<std::int64_t>::max()));
    }
    if (const auto value = tolerance.find("max_bad_pixels_percent")) {
        changes.maxSharePercent = value->number({.atLeast = 0.0, .below = 100.000001});
    }
    if (const auto value = tolerance.find("max_rmse_levels")) {
        changes.maxRmseLevels = value->number({.atLeast = 0.0, .below = 255.000001});
    }
    if (const auto value = tolerance.find("max_ambiguous_percent")) {
        changes.maxAmbiguousPercent = value->number({.atLeast = 0.0, .below = 100.000001});
    }
    return changes;
}

std::vector<std::string> readStrings(const JsonReader& value) {
    std::vector<std::string> strings;
    for (const JsonReader& element : value.elements()) {
        strings.push_back(element.text());
    }
    if (strings.empty()) {
        value.fail("must name at least one");
    }
    return strings;
}

std::vector<Precision> readPrecisions(const JsonReader& value) {
    std::vector<Precision> precisions;
    for (const JsonReader& element : value.elements()) {
        precisions.push_back(element.choice<Precision>({{"f32-naive", Precision::F32Naive},
                                                        {"f32", Precision::F32},
                                                        {"f64", Precision::F64},
                                                        {"f32-certified", Precision::F32Certified}}));
    }
    if (precisions.empty()) {
        value.fail("must name at least one (leave the key out for every precision)");
    }
    return precisions;
}

// The scene files under the file's directory, relative to it, for the globs to be checked on.
std::vector<std::string> scenesBeside(const fs::path& directory) {
    std::vector<std::string> scenes;
    for (const SceneFile& file : sceneFiles({directory.string()})) {
        if (file.problem.empty()) {
            scenes.push_back(relativeScenePath(directory, file.path));
        }
    }
    return scenes;
}

ExpectationEntry readEntry(const JsonReader& entry, const std::vector<std::string>& scenes) {
    entry.rejectUnknownKeys({"scenes", "precisions", "expect", "why", "tolerance"});
    ExpectationEntry result;
    const JsonReader patterns = entry.at("scenes");
    result.patterns = readStrings(patterns);
    for (std::size_t i = 0; i < result.patterns.size(); ++i) {
        const std::vector<std::string> one = {result.patterns[i]};
        if (std::none_of(scenes.begin(), scenes.end(), [&](const std::string& scene) { return matches(one, scene); })) {
            patterns.elements()[i].fail("matches no scene file under the expectations file's directory");
        }
    }
    if (const auto precisions = entry.find("precisions")) {
        result.precisions = readPrecisions(*precisions);
    }
    if (const auto expect = entry.find("expect")) {
        result.expect = expect->choice<Expected>(kExpectedNames);
    }
    if (const auto why = entry.find("why")) {
        result.why = why->text();
    }
    if (result.expect && *result.expect != Expected::Pass && result.why.empty()) {
        entry.at("why");  // an expected failure must say why: the message names the missing field
    }
    if (const auto tolerance = entry.find("tolerance")) {
        result.tolerance = readTolerance(*tolerance);
    }
    return result;
}

}  // namespace

std::string_view expectedName(Expected expected) {
    for (const auto& [name, value] : kExpectedNames) {
        if (value == expected) {
            return name;
        }
    }
    return "pass";
}

Expectations readExpectations(const std::string& path) {
    const Json document = parseFile(path);
    const std::string source = printable(path);  // the readers keep a reference to it
    const JsonReader root(document, source, "");
    root.rejectUnknownKeys({"schema", "expectations"});
    const JsonReader schemaField = root.at("schema");
    const std::string schema = schemaField.text();
    if (schema != "hexray-expectations/1") {
        schemaField.fail("unknown schema " + quotedForMessage(schema) + " (this hexray reads hexray-expectations/1)");
    }
    Expectations expectations;
    expectations.path = path;
    expectations.directory = fs::weakly_canonical(fs::absolute(path)).parent_path();
    const std::vector<std::string> scenes = scenesBeside(expectations.directory);
    const JsonReader entries = root.at("expectations");  // the elements' parent: it must outlive them
    for (const JsonReader& entry : entries.elements()) {
        expectations.entries.push_back(readEntry(entry, scenes));
        expectations.entries.back().place = source + ": " + displayPath(entry.path());
    }
    return expectations;
}

std::optional<std::string> findExpectations(const std::string& scenePath) {
    std::error_code error;
    fs::path directory = fs::weakly_canonical(fs::absolute(scenePath), error).parent_path();
    while (!error && !directory.empty()) {
        const fs::path candidate = directory / kExpectationsFileName;
        if (fs::is_regular_file(candidate, error)) {
            return candidate.string();
        }
        if (fs::exists(directory / ".git", error) || directory == directory.root_path()) {
            break;
        }
        directory = directory.parent_path();
    }
    return std::nullopt;
}

SceneExpectation expectationFor(const Expectations* expectations, const std::string& scenePath, Precision used,
                                const Tolerance& base, const ToleranceChanges& commandLine) {
    SceneExpectation result;
    ToleranceChanges changes;
    if (expectations) {
        const std::string relative = relativeScenePath(expectations->directory, scenePath);
        for (const ExpectationEntry& entry : expectations->entries) {
            const bool precisionApplies =
                entry.precisions.empty() ||
                std::find(entry.precisions.begin(), entry.precisions.end(), used) != entry.precisions.end();
            if (!precisionApplies || !matches(entry.patterns, relative)) {
                continue;
            }
            if (entry.expect) {
                result.expect = *entry.expect;
                result.why = entry.why;
                result.place = entry.place;
            }
            changes.update(entry.tolerance);
        }
    }
    changes.update(commandLine);
    result.tolerance = changes.appliedTo(base);
    return result;
}

std::string_view outcomeName(Outcome outcome) {
    switch (outcome) {
        case Outcome::Passed:
            return "passed";
        case Outcome::Expected:
            return "expected";
        case Outcome::NotJudged:
            return "not_judged";
        default:
            return "failed";
    }
}

namespace {

// "topology mismatches, ambiguous share": the limits a verdict exceeded.
std::string exceededLimits(const Verdict& verdict) {
    std::string limits;
    const auto add = [&](bool ok, const char* name) {
        if (!ok) {
            limits += (limits.empty() ? "" : ", ") + std::string(name);
        }
    };
    add(verdict.valuesOk, "invalid colours");
    add(verdict.topologyOk, "topology mismatches");
    add(verdict.ambiguousOk, "ambiguous share");
    add(verdict.shareOk, "pixels more than one level off");
    add(verdict.rmseOk, "8-bit RMSE");
    return limits;
}

bool onlyTooAmbiguous(const Verdict& verdict) {
    return !verdict.ambiguousOk && verdict.topologyOk && verdict.shareOk && verdict.rmseOk && verdict.valuesOk;
}

}  // namespace

JudgedOutcome outcomeOf(const Verdict& verdict, bool judged, const SceneExpectation& expectation) {
    if (!judged) {
        return {Outcome::NotJudged,
                "shown, not judged (the textbook formulation, kept to show what the robust one buys)"};
    }
    const bool passed = verdict.passed();
    switch (expectation.expect) {
        case Expected::TooAmbiguous:
            if (onlyTooAmbiguous(verdict)) {
                return {Outcome::Expected, "too ambiguous, as " + expectation.place + " expects: " + expectation.why};
            }
            return {Outcome::Failed, passed ? "passed, but " + expectation.place +
                                                  " expects it too ambiguous: narrow or remove that entry"
                                            : "exceeded " + exceededLimits(verdict) + ", where " + expectation.place +
                                                  " expects only the ambiguous share"};
        case Expected::Fail:
            if (!passed) {
                return {Outcome::Expected, "exceeded " + exceededLimits(verdict) + ", as " + expectation.place +
                                               " expects: " + expectation.why};
            }
            return {Outcome::Failed,
                    "passed, but " + expectation.place + " expects a failure: narrow or remove that entry"};
        default:
            return passed ? JudgedOutcome{Outcome::Passed, "within tolerance"}
                          : JudgedOutcome{Outcome::Failed, "exceeded " + exceededLimits(verdict)};
    }
}

}  // namespace hexray::cli
