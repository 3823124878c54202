#pragma once
// What a scene tree expects of `hexray compare` (docs/compare-expectations.md): a file named
// hexray-expectations.json beside the scenes sets, per scene glob and precision, tolerances and
// whether a comparison is expected to fail. Expectations are strict, as pytest's strict xfail:
// a comparison expected to fail that passes is a failure, so the file cannot rot unseen.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/scene_files.h"
#include "compare/compare.h"
#include "precision/precision.h"

namespace hexray::cli {

enum class Expected {
    Pass,
    TooAmbiguous,  // fails on the ambiguous share alone: near-tied on purpose
    Fail,          // fails, for any reason (a known defect, tracked elsewhere)
};

struct ExpectationEntry {
    std::vector<std::string> patterns;  // globs on scene paths relative to the file's directory
    std::vector<Precision> precisions;  // the precisions used that it applies to; empty = every one
    std::optional<Expected> expect;
    std::string why;
    ToleranceChanges tolerance;
    std::string place;  // "<file>: expectations[3]", for messages
};

struct Expectations {
    std::string path;  // the file
    std::filesystem::path directory;
    std::vector<ExpectationEntry> entries;
};

// Reads and checks the file: every key known, every value valid, every glob matching at least one
// scene file under the file's directory (a renamed scene must not leave a stale entry). Throws
// SceneError naming the file and the place.
Expectations readExpectations(const std::string& path);

// The nearest hexray-expectations.json in the scene file's directory or above it, not looking past
// a directory that holds .git (the repository's root); nullopt when there is none.
std::optional<std::string> findExpectations(const std::string& scenePath);

// What the file's entries that match say about one comparison (later entries win field by field),
// on top of `base`; then the command line's tolerance changes, which win over the file.
struct SceneExpectation {
    Expected expect = Expected::Pass;
    std::string why;
    std::string place;  // the entry that set `expect`, empty when none did
    Tolerance tolerance;
};
SceneExpectation expectationFor(const Expectations* expectations, const std::string& scenePath, Precision used,
                                const Tolerance& base, const ToleranceChanges& commandLine);

std::string_view expectedName(Expected expected);  // "pass", "too_ambiguous", "fail"

// Where a comparison leaves the gate: the count line's columns.
enum class Outcome {
    Passed,     // within its tolerance, as expected
    Expected,   // failed as its expectation says
    Failed,     // failed unexpectedly, passed where a failure was expected, or could not be loaded
    NotJudged,  // shown only (f32-naive rows of --all)
};
std::string_view outcomeName(Outcome outcome);  // "passed", "expected", "failed", "not_judged"

// The outcome and a sentence saying why, naming the limits exceeded or the entry that expected otherwise.
struct JudgedOutcome {
    Outcome outcome;
    std::string reason;
};
JudgedOutcome outcomeOf(const Verdict& verdict, bool judged, const SceneExpectation& expectation);

}  // namespace hexray::cli
