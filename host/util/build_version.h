#pragma once
// This build of hexray: its version (CMake's project version) and the git revision it was
// configured from. For `hexray --version` and the kernel cache's keys.

namespace hexray {

const char* hexrayVersion();
const char* hexrayGitRevision();

}  // namespace hexray
