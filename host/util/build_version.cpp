#include "util/build_version.h"

namespace hexray::inline util {

const char* hexrayVersion() {
    return HEXRAY_VERSION;
}

const char* hexrayGitRevision() {
    return HEXRAY_GIT_REVISION;
}

std::string buildVersion() {
    return std::string(hexrayVersion()) + " (git " + hexrayGitRevision() + ")";
}

}  // namespace hexray::util
