#pragma once
// An image written to a terminal is a screenful of noise that can leave the terminal in a strange
// state: such an output is refused before any work.

#include <string>

namespace hexray::cli {

// Whether writing to `path` would write to a terminal: "-" when standard output is one, or a
// path to a terminal device (/dev/tty, /dev/stdout on a terminal).
bool writesToTerminal(const std::string& path);

}  // namespace hexray::cli
