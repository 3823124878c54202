#pragma once
// The CPU reference renderer: the same model as the shader, written independently,
// in double precision and for clarity rather than speed.

#include "image/image.h"
#include "scene/scene.h"

namespace hexray {

// Renders one ray per pixel, rows spread over `threadCount` threads (0 = all cores).
Image renderOnCpu(const Scene& scene, unsigned threadCount = 0);

}  // namespace hexray
