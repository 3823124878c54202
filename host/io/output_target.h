#pragma once
// What writing an output path means, decided before anything is written. Nothing that is not a
// regular file is ever replaced: standard output, a device, a FIFO or a terminal is written
// directly. A regular file (existing or new) is written to a temporary file beside it and renamed
// over it when complete. A symlink is followed to the file it names, which is written; the
// link stays.

#include <sys/stat.h>

#include <filesystem>
#include <string>

namespace hexray::inline io {

enum class OutputKind {
    StandardOutput,  // "-", or a path to the file standard output already is
    Direct,          // an existing file that is not a regular file: written in place
    Replace,         // an existing regular file: replaced atomically, keeping its permissions
    Create,          // no file yet: created atomically
};

struct OutputTarget {
    OutputKind kind = OutputKind::Create;
    std::filesystem::path path;       // the file written: after following symlinks
    std::filesystem::path directory;  // Replace, Create: where the file (and its temporary) goes
    struct stat existing {};          // StandardOutput, Direct, Replace: the file as it is
};

// Throws OutputError "<given>: cannot create output file: <why>" when `given` cannot be an
// output: a directory, a missing or unwritable directory, a symlink loop.
OutputTarget resolveOutputTarget(const std::string& given);

// The directory `path` is in ("." for a bare name).
std::filesystem::path directoryOf(const std::filesystem::path& path);

// Why files cannot be created in `directory`, naming it ("" when they can).
std::string unwritableDirectoryReason(const std::filesystem::path& directory);

// `given` with its last component's symlinks followed, a dangling link's target included.
// Throws OutputError as resolveOutputTarget does for a link that cannot be read or a loop.
std::filesystem::path followSymlinks(const std::string& given);

}  // namespace hexray::io
