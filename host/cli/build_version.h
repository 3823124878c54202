#pragma once
// This build's version as `hexray --version` prints it, "0.1.0 (git 9317900a2b4c)": the project's
// version and the git revision CMake was configured from (HEXRAY_VERSION and HEXRAY_GIT_REVISION,
// defined for the files that include this; see CMakeLists.txt).

#include <string>

namespace hexray::cli {

inline std::string buildVersion() {
    return std::string(HEXRAY_VERSION) + " (git " + HEXRAY_GIT_REVISION + ")";
}

}  // namespace hexray::cli
