#include "io/open_file_limit.h"

#include <sys/resource.h>

#include <limits>

namespace hexray::inline io {
namespace {

std::uint64_t count(rlim_t limit) {
    return limit == RLIM_INFINITY ? std::numeric_limits<std::uint64_t>::max() : std::uint64_t(limit);
}

}  // namespace

std::uint64_t raiseOpenFileLimit(std::uint64_t needed) {
    rlimit limit{};
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) {
        return 0;
    }
    if (count(limit.rlim_cur) < needed && limit.rlim_cur != limit.rlim_max) {
        rlimit raised = limit;
        raised.rlim_cur = limit.rlim_max;
        if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) {
            limit = raised;
        }
    }
    return count(limit.rlim_cur);
}

}  // namespace hexray::io
