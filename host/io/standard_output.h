#pragma once
// Standard output as a destination for data (`-o -`): when a command writes an image or CSV
// there, the text it would print there goes to standard error instead, so the two never mix.

#include <string>
#include <vector>

namespace hexray::inline io {

// Whether writing to `path` means writing to this process's standard output: "-", or a path
// to the same file or pipe (/dev/stdout, /proc/self/fd/1, the file stdout is redirected to). A
// device (a terminal, /dev/null) is simply written directly.
bool namesStandardOutput(const std::string& path);

// `path` for messages: "standard output" for "-", else the path with its control characters
// escaped (util/printable.h).
std::string displayName(const std::string& path);

// If one of `outputs` names standard output, keeps standard output for data and sends what is
// printed to it (printf, std::cout) to standard error; those paths go on naming the data's
// destination. Call before anything is printed. Throws OutputError if the descriptors cannot be
// set up.
void reserveStandardOutputForData(const std::vector<std::string>& outputs);

// The descriptor that data for standard output goes to: the original standard output.
int standardOutputDescriptor();

}  // namespace hexray::io
