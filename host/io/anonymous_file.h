#pragma once
// A scratch file with no name, for an encoder that must seek back in what it wrote (OpenEXR's
// offset table) when its output cannot seek: nothing is left behind, however the process ends.

#include <cstdio>
#include <memory>
#include <string>

namespace hexray::inline io {

struct CloseFile {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePointer = std::unique_ptr<std::FILE, CloseFile>;

// The directory scratch files go into: $TMPDIR, else /tmp.
std::string scratchDirectory();

// A new empty file open for reading and writing in scratchDirectory(): unnamed (O_TMPFILE), or,
// where the file system cannot do that, named and removed at once. Null, with errno set, on
// failure.
FilePointer openAnonymousFile();

}  // namespace hexray::io
