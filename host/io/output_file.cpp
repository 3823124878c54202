#include "io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "io/output_error.h"
#include "io/removed_on_signal.h"
#include "io/stale_temporaries.h"
#include "io/standard_output.h"
#include "io/temporary_names.h"

namespace hexray::inline io {
namespace {

std::string systemError() {
    return std::strerror(errno);
}

mode_t newFileMode() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

// An existing file's permissions and, where the process may (root), its owner and group.
void keepAttributes(int descriptor, const struct stat& existing) {
    ::fchmod(descriptor, existing.st_mode & 07777);
    if (existing.st_uid != ::geteuid() || existing.st_gid != ::getegid()) {
        if (::fchown(descriptor, existing.st_uid, existing.st_gid) == 0) {
            ::fchmod(descriptor, existing.st_mode & 07777);  // chown clears set-id bits
        }
    }
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : name_(displayName(path)), target_(resolveOutputTarget(path)) {
    int descriptor = -1;
    switch (target_.kind) {
        case OutputKind::StandardOutput:
            descriptor = ::fcntl(standardOutputDescriptor(), F_DUPFD_CLOEXEC, 3);
            break;
        case OutputKind::Direct:
            descriptor = ::open(target_.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
            break;
        case OutputKind::Replace:
        case OutputKind::Create:
            openTemporary();
            return;
    }
    if (descriptor < 0 || !(file_ = ::fdopen(descriptor, "wb"))) {
        const std::string why = systemError();
        if (descriptor >= 0) {
            ::close(descriptor);
        }
        fail("cannot create output file", why);
    }
}

void OutputFile::openTemporary() {
    removeStaleTemporaries(target_.directory);
    RegisteredTemporary temporary = createTemporary(
        partialFilePattern(target_.directory, target_.path.filename().string()), RemovedOnSignal::Kind::File);
    if (temporary.descriptor < 0) {
        fail("cannot create output file", systemError());
    }
    const int descriptor = temporary.descriptor;
    temporaryPath_ = temporary.path;
    removal_ = std::move(temporary.removal);
    holdAsLive(descriptor);
    if (target_.kind == OutputKind::Replace) {
        keepAttributes(descriptor, target_.existing);
    } else {
        ::fchmod(descriptor, newFileMode());  // created 0600
    }
    file_ = ::fdopen(descriptor, "wb");
    if (!file_) {
        // A throwing constructor runs no destructor: clean up here.
        const std::string why = systemError();
        ::close(descriptor);
        ::unlink(temporaryPath_.c_str());
        fail("cannot create output file", why);
    }
}

OutputFile::~OutputFile() {
    if (file_) {
        std::fclose(file_);
    }
    if (!temporaryPath_.empty()) {
        ::unlink(temporaryPath_.c_str());
    }
}

void OutputFile::commit() {
    std::FILE* file = file_;
    file_ = nullptr;
    const bool regular = !temporaryPath_.empty();
    errno = 0;
    bool written = std::fflush(file) == 0 && !std::ferror(file);
    std::string why = errno != 0 ? systemError() : "a write failed";
    if (written && regular && ::fsync(::fileno(file)) != 0) {
        written = false;
        why = systemError();
    }
    if (std::fclose(file) != 0 && written) {
        written = false;
        why = systemError();
    }
    if (!written) {
        fail("cannot write", why);
    }
    if (regular && ::rename(temporaryPath_.c_str(), target_.path.c_str()) != 0) {
        fail("cannot write", systemError());
    }
    temporaryPath_.clear();
    removal_.reset();
}

void OutputFile::fail(const std::string& what, const std::string& why) const {
    throw OutputError(name_ + ": " + what + ": " + why);
}

}  // namespace hexray::io
