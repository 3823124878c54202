#include "io/untrusted_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace hexray::inline io {
namespace {

std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    return "not a file";
}

std::string withUnit(std::uint64_t bytes) {
    return bytes % (1u << 20) == 0 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

}  // namespace

UntrustedFile::UntrustedFile(const std::filesystem::path& path, std::uint64_t maxBytes) {
    descriptor_ = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (descriptor_ < 0) {
        const int error = errno;
        absent_ = error == ENOENT || error == ENOTDIR;
        problem_ = absent_          ? "nothing is there"
                   : error == ELOOP ? "it is a symbolic link"
                                    : std::string("it cannot be opened: ") + std::strerror(error);
        return;
    }
    if (::fstat(descriptor_, &status_) != 0) {
        problem_ = std::string("it cannot be examined: ") + std::strerror(errno);
    } else if (!S_ISREG(status_.st_mode)) {
        problem_ = "it is " + kindOf(status_.st_mode) + ", not a regular file";
    } else if (std::uint64_t(status_.st_size) > maxBytes) {
        problem_ = "it holds " + std::to_string(status_.st_size) + " bytes, more than an entry may (" +
                   withUnit(maxBytes) + ")";
    }
}

UntrustedFile::~UntrustedFile() {
    if (descriptor_ >= 0) {
        ::close(descriptor_);
    }
}

std::optional<std::string> UntrustedFile::read() {
    if (absent_ || !problem_.empty()) {
        return std::nullopt;
    }
    // One byte more than fstat said: a file that grew since is seen to have.
    std::string bytes(std::size_t(status_.st_size) + 1, '\0');
    std::size_t filled = 0;
    while (filled < bytes.size()) {
        const ssize_t got = ::read(descriptor_, bytes.data() + filled, bytes.size() - filled);
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got < 0) {
            problem_ = std::string("it cannot be read: ") + std::strerror(errno);
            return std::nullopt;
        }
        if (got == 0) {
            break;
        }
        filled += std::size_t(got);
    }
    if (filled != std::size_t(status_.st_size)) {
        problem_ = "it changed while it was read";
        return std::nullopt;
    }
    bytes.resize(filled);
    return bytes;
}

void UntrustedFile::touch() const {
    if (descriptor_ >= 0) {
        ::futimens(descriptor_, nullptr);
    }
}

bool UntrustedFile::stillNamedBy(const std::filesystem::path& path) const {
    struct stat now {};
    return descriptor_ >= 0 && ::lstat(path.c_str(), &now) == 0 && now.st_dev == status_.st_dev &&
           now.st_ino == status_.st_ino;
}

}  // namespace hexray::io
