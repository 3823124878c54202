#include "cli/terminal_output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hexray::cli {

bool writesToTerminal(const std::string& path) {
    if (path == "-") {
        return ::isatty(STDOUT_FILENO) != 0;
    }
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0 || !S_ISCHR(status.st_mode)) {
        return false;
    }
    // Opened to ask, never written: without O_NOCTTY it could become this process's terminal.
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (descriptor < 0) {
        return false;
    }
    const bool terminal = ::isatty(descriptor) != 0;
    ::close(descriptor);
    return terminal;
}

}  // namespace hexray::cli
