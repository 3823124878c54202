// hexray: renders scene files with a Vulkan compute shader (or the CPU reference) and compares
// the two (cli/command_line.cpp defines the command line).

#include "cli/command_line.h"

int main(int argc, char** argv) {
    return hexray::cli::runCommandLine(argc, argv);
}
