#include "io/standard_input.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "io/anonymous_file.h"

namespace hexray::inline io {

namespace {

constexpr const char* kName = "standard input";

[[noreturn]] void fail(const std::string& what, int error) {
    throw InputError(std::string(kName) + ": " + what + ": " + std::strerror(error));
}

}  // namespace

ReadOnlyFile standardInputAsFile() {
    FilePointer scratch = openAnonymousFile();
    if (!scratch) {
        fail("cannot create a scratch file in " + scratchDirectory(), errno);
    }
    std::array<char, 1 << 16> buffer{};
    for (;;) {
        const ssize_t got = ::read(STDIN_FILENO, buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            fail("cannot read", errno);
        }
        if (got == 0) {
            break;
        }
        if (std::fwrite(buffer.data(), 1, std::size_t(got), scratch.get()) != std::size_t(got)) {
            fail("cannot copy to a scratch file in " + scratchDirectory(), errno);
        }
    }
    if (std::fflush(scratch.get()) != 0) {
        fail("cannot copy to a scratch file in " + scratchDirectory(), errno);
    }
    const int descriptor = ::fcntl(::fileno(scratch.get()), F_DUPFD_CLOEXEC, 0);
    if (descriptor < 0) {
        fail("cannot reopen the scratch file", errno);
    }
    return ReadOnlyFile(descriptor, kName);
}

}  // namespace hexray::io
