#pragma once
// What the subcommands share: turning failures into messages and exit codes, loading the
// scene with the command line's overrides, and the validation verdict.

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "util/milliseconds_since.h"
#include "cli/commands.h"
#include "scene/scene.h"
#include "vulkan/vulkan_context.h"

namespace hexray::cli {

// What a band of rows may hold, for the renders whose rows come back as floats (the CPU
// reference, compare, AOVs): memory grows with the image's width, not its area.
inline constexpr std::size_t kBandBytes = std::size_t{32} << 20;

// Prints "hexray: error: …" on standard error and keeps the message for errorsPrinted().
void printError(const std::string& message);
// Every message printError has printed in this process, in order (for --json's "exit").
const std::vector<std::string>& errorsPrinted();

// The exit code for a Vulkan failure of this kind.
int exitCodeFor(VulkanFailure failure);

// Runs a command, turning each kind of failure into its message and exit code (out of memory:
// exit code 6 and a message that says which size to reduce).
int guarded(const std::function<int()>& command);

// Loads the scene with the command line's overrides, showing progress for a large file on a
// terminal. With `identity`, also the file's identity (strip/strip_stamp.h, sceneTextIdentity).
Scene loadScene(const std::string& path, const ImageOverride& image, std::string* identity = nullptr);

// The command line's replacements for the scene's image size and samples, checked like the file's.
void applyImageOverride(Scene& scene, const ImageOverride& image);

// Validation messages fail the command: a tester's run must be clean, not merely finish.
// `commandCode` wins when it is already a failure.
int withValidationVerdict(int commandCode, const ValidationLog& log);

}  // namespace hexray::cli
