#pragma once
// The names of hexray's temporary files and directories. Each says what it is, so that one a
// killed process leaves behind explains itself, and so that a later run can recognise (and
// remove, see stale_temporaries.h) only hexray's own.

#include <filesystem>
#include <string>
#include <string_view>

namespace hexray::inline io {

// `.hexray-partial-<target name>.XXXXXX`: an output being written, renamed over the target
// when complete.
inline constexpr std::string_view kPartialFilePrefix = ".hexray-partial-";
// `.hexray-aov-XXXXXX`: a set of AOVs being written, moved into its directory when complete.
inline constexpr std::string_view kAovStagingPrefix = ".hexray-aov-";
// `.hexray-report-XXXXXX`: a comparison report being written, moved into its directory when complete.
inline constexpr std::string_view kReportStagingPrefix = ".hexray-report-";

// `pattern` with its trailing "XXXXXX" replaced by random letters and digits.
std::string randomName(const std::string& pattern);

// The pattern (see randomName) for a temporary file beside `targetName` in `directory`. The target's name
// is shortened (at a character boundary) as far as needed to keep the whole name within the
// directory's file-name limit, so a target of any valid length gets a temporary.
std::string partialFilePattern(const std::filesystem::path& directory, const std::string& targetName);

}  // namespace hexray::io
