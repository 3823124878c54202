// hexray: renders scene files with a Vulkan compute shader (or the CPU reference) and compares
// the two (cli/command_line.cpp defines the command line).

#include <malloc.h>

#include "cli/command_line.h"

int main(int argc, char** argv) {
    // A large scene allocates and frees arrays of tens of megabytes in turn (the file's text, the
    // candidate lists' footprints, the device's buffers under lavapipe). glibc maps each such array
    // afresh and unmaps it when freed, so every page of the next one is faulted in again; from the
    // heap, the next array reuses the pages the last one freed (fewer page faults, and a lower peak).
    constexpr int kMappedFromBytes = 1 << 30;
    mallopt(M_MMAP_THRESHOLD, kMappedFromBytes);
    return hexray::cli::runCommandLine(argc, argv);
}
