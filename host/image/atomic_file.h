#pragma once
// A file that appears at its path only when complete. It is written to a temporary file
// beside the target and renamed over it by commit(); destroyed without commit() (a failure, an
// exception) or interrupted by SIGINT or SIGTERM, the temporary file is removed, and whatever
// was at the path before is untouched.

#include <cstdio>
#include <filesystem>
#include <string>

namespace hexray {

class AtomicFile {
public:
    // Throws ImageIoError naming the target when the temporary file cannot be created.
    explicit AtomicFile(const std::filesystem::path& target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::FILE* stream() const { return file_; }
    const std::filesystem::path& target() const { return target_; }

    // Flushes, syncs, closes and renames into place; throws ImageIoError on any failure.
    void commit();

    // Throws ImageIoError "<target>: <what>: <why>".
    [[noreturn]] void fail(const std::string& what, const std::string& why) const;

private:
    std::filesystem::path target_;
    std::string temporaryPath_;  // empty once committed
    std::FILE* file_ = nullptr;
    int signalSlot_ = -1;  // where the signal handler finds temporaryPath_
};

}  // namespace hexray
