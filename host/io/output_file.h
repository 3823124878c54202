#pragma once
// An output file, written where the user said and nowhere else (see output_target.h for what
// each kind of path means). A regular file appears at its path only when complete: it is written
// to a temporary file beside it (`.hexray-partial-…`, see temporary_names.h) and renamed over it
// by commit(), keeping an existing file's permissions (and, for root, its owner). Destroyed
// without commit() (a failure, an exception) or ended by a catchable signal, it removes the
// temporary file, and whatever was at the path before is untouched. A file with several hard
// links is replaced under the name given; its other names keep the old contents.
// Standard output, devices, FIFOs and terminals are written directly, and their write errors
// reported (ENOSPC from /dev/full as much as from a full disk).

#include <cstdio>
#include <memory>
#include <string>

#include "io/output_target.h"

namespace hexray::inline io {

class RemovedOnSignal;

class OutputFile {
public:
    // Throws OutputError naming `path` when it cannot be opened (or its temporary created).
    explicit OutputFile(const std::string& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::FILE* stream() const { return file_; }
    // The path as given, or "standard output", for messages.
    const std::string& name() const { return name_; }
    // Whether the stream is a regular file of this object's own from its first byte (a new file
    // or the temporary that replaces one), where a writer may seek back. Standard output (even
    // a file), devices, FIFOs and terminals are written straight through, in order.
    bool seekable() const { return !temporaryPath_.empty(); }

    // Flushes, syncs, closes and (for a regular file) renames into place; throws OutputError
    // on any failure.
    void commit();

    // Throws OutputError "<name>: <what>: <why>".
    [[noreturn]] void fail(const std::string& what, const std::string& why) const;

private:
    void openTemporary();

    std::string name_;
    OutputTarget target_;
    std::string temporaryPath_;  // Replace and Create, until committed
    std::unique_ptr<RemovedOnSignal> removal_;
    std::FILE* file_ = nullptr;
};

}  // namespace hexray::io
