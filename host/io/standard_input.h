#pragma once
// Standard input (`-` as an input file) as a file that can be read at any offset: what it carries
// is copied into an unnamed scratch file (io/anonymous_file.h), so readers that seek (OpenEXR's
// offset table) read a pipe as they read a file.

#include "io/read_only_file.h"

namespace hexray::inline io {

// Reads standard input to its end. Throws InputError naming "standard input" when it cannot be
// read, or the scratch file cannot be written.
ReadOnlyFile standardInputAsFile();

}  // namespace hexray::io
