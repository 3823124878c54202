#pragma once
// This build of hexray: its version (CMake's project version) and the git revision it was
// configured from. For `hexray --version`, the kernel cache's keys and the strips' stamps.

#include <string>

namespace hexray::inline util {

const char* hexrayVersion();
const char* hexrayGitRevision();

// Both as `hexray --version` prints them: "0.1.0 (git 9317900a2b4c)".
std::string buildVersion();

}  // namespace hexray::util
