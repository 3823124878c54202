#pragma once
// The command line's mistakes in hexray's words: CLI11's parse errors (an unknown option, a
// missing argument or value, options that exclude each other) reworded as one "hexray: error:"
// line with "did you mean …" where a known name is near, and exit code 2. Help and --version
// are not mistakes: they print and exit 0.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace hexray::cli {

// The error message for `error`, which parsing `app` threw (empty for help, which is printed).
// Returns the exit code.
int reportParseError(CLI::App& app, const CLI::ParseError& error);

// The first word of the command line that is not an option, when it names no command: the
// message for it (with the nearest command's name, if one is near).
std::optional<std::string> unknownCommandMessage(int argc, char** argv, const CLI::App& app);

}  // namespace hexray::cli
