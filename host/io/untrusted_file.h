#pragma once
// A file at a name anyone could have put anything at (a cache's entry). It is opened once, without
// following a symbolic link, without blocking (a FIFO with no writer) and without becoming a
// controlling terminal, then fstat'ed: only a regular file of at most the size allowed is read,
// and only from that descriptor, so a FIFO, a device, a directory or a link to /dev/zero can
// neither hang the reader nor fill its memory.

#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace hexray::inline io {

class UntrustedFile {
public:
    UntrustedFile(const std::filesystem::path& path, std::uint64_t maxBytes);
    ~UntrustedFile();
    UntrustedFile(const UntrustedFile&) = delete;
    UntrustedFile& operator=(const UntrustedFile&) = delete;

    // Nothing is at the name (or its directory is missing or not a directory).
    bool absent() const { return absent_; }
    // Why the file cannot be read ("it is a FIFO, not a regular file", ...); empty when it can.
    const std::string& problem() const { return problem_; }

    // The whole file, when it can be read; else nothing, and problem() says why (a read error, or
    // the file changed size while it was read).
    std::optional<std::string> read();
    // Marks the file as used now (its modification time); failures are ignored.
    void touch() const;
    // Whether `path` still names the file opened here (not a newer file renamed over it since).
    bool stillNamedBy(const std::filesystem::path& path) const;

private:
    int descriptor_ = -1;
    struct stat status_ {};
    bool absent_ = false;
    std::string problem_;
};

}  // namespace hexray::io
