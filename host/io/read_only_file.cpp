#include "io/read_only_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace hexray::inline io {

ReadOnlyFile::ReadOnlyFile(const std::string& path)
    : descriptor_(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY)), name_(path) {
    if (descriptor_ < 0) {
        throw InputError(name_ + ": cannot open: " + std::strerror(errno));
    }
}

ReadOnlyFile::ReadOnlyFile(int descriptor, std::string name) : descriptor_(descriptor), name_(std::move(name)) {}

ReadOnlyFile::~ReadOnlyFile() {
    if (descriptor_ >= 0) {
        ::close(descriptor_);
    }
}

ReadOnlyFile::ReadOnlyFile(ReadOnlyFile&& other) noexcept
    : descriptor_(std::exchange(other.descriptor_, -1)), name_(std::move(other.name_)) {}

ReadOnlyFile& ReadOnlyFile::operator=(ReadOnlyFile&& other) noexcept {
    if (this != &other) {
        if (descriptor_ >= 0) {
            ::close(descriptor_);
        }
        descriptor_ = std::exchange(other.descriptor_, -1);
        name_ = std::move(other.name_);
    }
    return *this;
}

std::uint64_t ReadOnlyFile::size() const {
    struct stat status {};
    if (::fstat(descriptor_, &status) != 0) {
        throw InputError(name_ + ": cannot read: " + std::strerror(errno));
    }
    return std::uint64_t(status.st_size);
}

std::size_t ReadOnlyFile::readAt(std::uint64_t offset, std::span<std::byte> bytes) const {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t read = ::pread(descriptor_, bytes.data() + done, bytes.size() - done, off_t(offset + done));
        if (read < 0 && errno == EINTR) {
            continue;
        }
        if (read < 0) {
            throw InputError(name_ + ": cannot read: " + std::strerror(errno));
        }
        if (read == 0) {
            break;
        }
        done += std::size_t(read);
    }
    return done;
}

}  // namespace hexray::io
