#pragma once
// Text hexray did not write (file names, scene keys and strings, a strip's stamp, words from the
// command line), made safe to quote in a message: a control character in it would otherwise
// reach the terminal and act there (move the cursor, recolour, retitle the window).

#include <string>
#include <string_view>

namespace hexray::inline util {

// `text` with C0 controls and DEL as \xNN (ESC: \x1b), C1 controls (U+0080..U+009F, which some
// terminals obey too) as \u0080..\u009f, and each byte that is not part of valid UTF-8 as \xNN.
// Everything else, other languages' letters included, is kept as it is.
std::string printable(std::string_view text);

}  // namespace hexray::util
