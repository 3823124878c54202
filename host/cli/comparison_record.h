#pragma once
// One comparison of one scene in one precision as every output of `hexray compare` reports it:
// the table, the detailed report, --json, --junit and --report read the same record.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/compare_expectations.h"
#include "compare/compare.h"
#include "precision/precision.h"
#include "scene/scene.h"

namespace hexray::cli {

struct ComparisonRecord {
    std::string scenePath;
    std::string name;       // the table's: the path under the directory given, without .json
    std::string loadError;  // the scene could not be loaded: why (no field below applies then)
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    Encoding encoding = Encoding::Srgb;
    Precision requested = Precision::Auto;
    Precision precision = Precision::Auto;  // the one used
    bool chosenByAuto = false;              // `precision` is the one auto picks for this scene
    bool judged = true;
    RenderComparison comparison;
    std::optional<double> flipMean;  // of the 8-bit outputs, every pixel; none past compare/band_flip.h's bound
    SceneExpectation expectation;    // with the tolerance it was held to
    Verdict verdict;
    JudgedOutcome outcome{Outcome::Failed, ""};
    double gpuMilliseconds = 0;
    double cpuMilliseconds = 0;
    unsigned cpuThreads = 0;
    std::string reportImages;  // --report: the stem of its images' names (report_layout.h); empty for none
};

// The count line's figures.
struct OutcomeCounts {
    std::uint64_t passed = 0;
    std::uint64_t expected = 0;
    std::uint64_t failed = 0;
    std::uint64_t notJudged = 0;

    void add(Outcome outcome) {
        (outcome == Outcome::Passed     ? passed
         : outcome == Outcome::Expected ? expected
         : outcome == Outcome::Failed   ? failed
                                        : notJudged)++;
    }
    bool gatePassed() const { return failed == 0; }
};

inline OutcomeCounts countOutcomes(const std::vector<ComparisonRecord>& records) {
    OutcomeCounts counts;
    for (const ComparisonRecord& record : records) {
        counts.add(record.outcome.outcome);
    }
    return counts;
}

}  // namespace hexray::cli
