#pragma once
// `hexray compare --junit FILE`: the comparisons as JUnit XML, the format GitLab, Jenkins and
// GitHub's test reporters read. One test case per scene and precision: a failure carries the
// metrics and the limits exceeded; an expected failure and a row shown but not judged are skipped
// (as pytest reports xfail); a scene that cannot be loaded is an error.

#include <string>
#include <vector>

#include "cli/comparison_record.h"

namespace hexray::cli {

// `device`: the Vulkan device's name, or empty. Written whole or not at all (io/output_file.h).
void writeJunit(const std::string& path, const std::vector<ComparisonRecord>& records, const std::string& device);

// One line of a comparison's metrics against its limits, as the failure message's text.
std::string metricsLine(const ComparisonRecord& record);

}  // namespace hexray::cli
