#pragma once
// Scene files are UTF-8 (with or without a byte order mark). Text saved as UTF-16 or UTF-32, as
// some Windows editors and PowerShell's redirection do, is recognised before parsing, so that it
// gets a message naming the encoding instead of a syntax error at its first NUL byte.

#include <optional>
#include <string>
#include <string_view>

namespace hexray::inline scene {

// For text in UTF-16 or UTF-32: "the file is UTF-16 (little-endian) text, and scene files are
// UTF-8: convert it, ..." Recognised by a byte order mark or, without one, by the NUL bytes of
// its first character, which JSON text requires to be ASCII (RFC 4627, section 3). nullopt for
// anything else: the parser judges that.
std::optional<std::string> wideEncodingProblem(std::string_view text);

}  // namespace hexray::scene
