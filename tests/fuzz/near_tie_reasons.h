#pragma once
// Why a scene may honestly leave many pixels near-tied, whatever the arithmetic: something lies
// on a decision's boundary (a light or the camera on a surface, surfaces touching), or a feature is
// finer than the renderers can resolve. The differential check holds other scenes to compare's
// ambiguity limit; for these the limit measures the scene, not the renderers.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace hexray::test {

// What is on a boundary or below resolution in `scene`, one line per reason; empty when nothing is.
std::vector<std::string> nearTieReasons(const Scene& scene);

}  // namespace hexray::test
