#pragma once
// The whole command line: parses argv, runs the subcommand it names and returns the exit code.
// main() only calls it, so that the command line compiles with the rest of its layer.

namespace hexray::cli {

int runCommandLine(int argc, char** argv);

}  // namespace hexray::cli
