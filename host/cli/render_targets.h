#pragma once
// Which file each scene of `hexray render` goes to, decided (and checked for collisions) before
// any work.

#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "image/image_format.h"

namespace hexray::cli {

struct RenderTarget {
    std::string scenePath;
    std::string outputPath;
    std::optional<ImageFormat> format;  // none: an extension hexray does not write
    std::string problem;                // a directory that could not be searched: no output (scene_files.h)
};

// The scenes named (directories expanded to their *.json files), each with its output: `-o` as
// given for one scene, or, when `-o` is a directory (the only choice for several scenes),
// <scene name>.png in it; without `-o`, <scene name>.png here. A strip's default name is
// <scene name>.strip-I-of-N.png. Throws SceneError (exit code 2) for a `-o` several scenes cannot
// share, or two scenes whose outputs would have the same name; OutputError (exit code 5) for a
// `-o` directory that does not exist.
std::vector<RenderTarget> renderTargets(const RenderOptions& options);

}  // namespace hexray::cli
