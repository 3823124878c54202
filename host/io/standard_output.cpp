#include "io/standard_output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "io/output_error.h"
#include "util/printable.h"

namespace hexray::inline io {
namespace {

int dataDescriptor = STDOUT_FILENO;
// Paths that named standard output when it was reserved: /proc/self/fd/1 names another file now.
std::vector<std::string> reservedNames;

}  // namespace

bool namesStandardOutput(const std::string& path) {
    if (path == "-" || std::find(reservedNames.begin(), reservedNames.end(), path) != reservedNames.end()) {
        return true;
    }
    // A terminal or /dev/null is the same written either way, and text beside the image does no
    // harm there; a file or pipe reached through /dev/stdout must not be replaced or mixed.
    struct stat output {};
    struct stat named {};
    return ::fstat(standardOutputDescriptor(), &output) == 0 && ::stat(path.c_str(), &named) == 0 &&
           output.st_dev == named.st_dev && output.st_ino == named.st_ino && !S_ISCHR(named.st_mode);
}

std::string displayName(const std::string& path) {
    return path == "-" ? "standard output" : printable(path);
}

void reserveStandardOutputForData(const std::vector<std::string>& outputs) {
    for (const std::string& output : outputs) {
        if (!output.empty() && namesStandardOutput(output)) {
            reservedNames.push_back(output);
        }
    }
    if (reservedNames.empty() || dataDescriptor != STDOUT_FILENO) {
        return;
    }
    const int data = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
    if (data < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        throw OutputError(std::string("standard output: cannot set it aside for the image: ") + std::strerror(errno));
    }
    dataDescriptor = data;
}

int standardOutputDescriptor() {
    return dataDescriptor;
}

}  // namespace hexray::io
