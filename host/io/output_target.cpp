#include "io/output_target.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/output_error.h"
#include "io/standard_output.h"
#include "util/printable.h"

namespace hexray::inline io {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSymlinkHops = 40;  // as the kernel's ELOOP limit

[[noreturn]] void refuse(const std::string& given, const std::string& why) {
    throw OutputError(printable(given) + ": cannot create output file: " + why);
}

void requireWritableDirectory(const std::string& given, const fs::path& directory) {
    const std::string why = unwritableDirectoryReason(directory);
    if (!why.empty()) {
        refuse(given, why);
    }
}

}  // namespace

fs::path directoryOf(const fs::path& path) {
    return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

std::string unwritableDirectoryReason(const fs::path& directory) {
    struct stat status {};
    int error = 0;
    if (::stat(directory.c_str(), &status) != 0) {
        error = errno;
    } else if (!S_ISDIR(status.st_mode)) {
        error = ENOTDIR;
    } else if (::access(directory.c_str(), W_OK | X_OK) != 0) {
        error = errno;
    }
    return error == 0 ? "" : "directory " + printable(directory.string()) + ": " + std::strerror(error);
}

fs::path followSymlinks(const std::string& given) {
    fs::path path = given;
    for (int hop = 0; hop < kMaxSymlinkHops; ++hop) {
        std::error_code error;
        if (!fs::is_symlink(fs::symlink_status(path, error))) {
            return path;
        }
        const fs::path target = fs::read_symlink(path, error);
        if (error) {
            refuse(given, error.message());
        }
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    refuse(given, std::strerror(ELOOP));
}

OutputTarget resolveOutputTarget(const std::string& given) {
    OutputTarget target;
    if (namesStandardOutput(given)) {
        target.kind = OutputKind::StandardOutput;
        ::fstat(standardOutputDescriptor(), &target.existing);
        return target;
    }
    target.path = followSymlinks(given);
    target.directory = directoryOf(target.path);
    if (::stat(target.path.c_str(), &target.existing) != 0) {
        if (errno != ENOENT) {
            refuse(given, std::strerror(errno));
        }
        requireWritableDirectory(given, target.directory);
        target.kind = OutputKind::Create;
        return target;
    }
    if (S_ISDIR(target.existing.st_mode)) {
        refuse(given, std::strerror(EISDIR));
    }
    if (!S_ISREG(target.existing.st_mode)) {
        if (::access(target.path.c_str(), W_OK) != 0) {
            refuse(given, std::strerror(errno));
        }
        target.kind = OutputKind::Direct;
        return target;
    }
    requireWritableDirectory(given, target.directory);
    target.kind = OutputKind::Replace;
    return target;
}

}  // namespace hexray::io
