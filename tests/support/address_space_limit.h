#pragma once
// Caps this process's address space at its current size plus a headroom while in scope, so that
// an allocation larger than the headroom fails (std::bad_alloc, or a report under ASan) instead
// of taking the machine's memory: how a test shows that nothing large was allocated.

#include <sys/resource.h>
#include <unistd.h>

#include <cstddef>
#include <fstream>

#include <gtest/gtest.h>

namespace hexray::test {

class AddressSpaceLimit {
public:
    explicit AddressSpaceLimit(std::size_t headroomBytes) {
        std::size_t pages = 0;
        std::ifstream("/proc/self/statm") >> pages;  // the address space's size, in pages
        EXPECT_GT(pages, 0u);
        EXPECT_EQ(::getrlimit(RLIMIT_AS, &previous_), 0);
        rlimit limit = previous_;
        limit.rlim_cur = pages * std::size_t(::sysconf(_SC_PAGESIZE)) + headroomBytes;
        if (previous_.rlim_max != RLIM_INFINITY && limit.rlim_cur > previous_.rlim_max) {
            limit.rlim_cur = previous_.rlim_max;
        }
        EXPECT_EQ(::setrlimit(RLIMIT_AS, &limit), 0);
    }
    ~AddressSpaceLimit() { ::setrlimit(RLIMIT_AS, &previous_); }
    AddressSpaceLimit(const AddressSpaceLimit&) = delete;
    AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;

private:
    rlimit previous_{};
};

}  // namespace hexray::test
