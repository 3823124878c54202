#include "io/remove_without_following.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace hexray::inline io {
namespace {

constexpr int kMaxDepth = 32;

// The names in the open directory `descriptor` (which stays open).
std::vector<std::string> namesIn(int descriptor) {
    std::vector<std::string> names;
    const int copy = ::dup(descriptor);
    DIR* directory = copy >= 0 ? ::fdopendir(copy) : nullptr;
    if (!directory) {
        if (copy >= 0)
            ::close(copy);
        return names;
    }
    while (const dirent* entry = ::readdir(directory)) {
        if (std::strcmp(entry->d_name, ".") != 0 && std::strcmp(entry->d_name, "..") != 0) {
            names.emplace_back(entry->d_name);
        }
    }
    ::closedir(directory);
    return names;
}

bool removeAt(int parent, const std::string& name, int depthLeft) {
    if (::unlinkat(parent, name.c_str(), 0) == 0 || errno == ENOENT) {
        return true;
    }
    if (errno != EISDIR || depthLeft == 0) {
        return false;
    }
    const int descriptor = ::openat(parent, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (descriptor < 0) {
        return false;
    }
    bool removed = true;
    for (const std::string& child : namesIn(descriptor)) {
        removed = removeAt(descriptor, child, depthLeft - 1) && removed;
    }
    ::close(descriptor);
    return removed && (::unlinkat(parent, name.c_str(), AT_REMOVEDIR) == 0 || errno == ENOENT);
}

}  // namespace

bool removeWithoutFollowing(const std::filesystem::path& directory, const std::string& name) {
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
        return false;
    }
    const int parent = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (parent < 0) {
        return errno == ENOENT;
    }
    const bool removed = removeAt(parent, name, kMaxDepth);
    ::close(parent);
    return removed;
}

}  // namespace hexray::io
