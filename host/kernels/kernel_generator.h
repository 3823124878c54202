#pragma once
// Writes the GLSL of a kernel for one scene's structure (SceneCode, decided by planRender): the
// scene's "main" only, with the node tests unrolled in order and only the shaders, lights and
// shadow tests the scene uses, each calling the small functions of the shader library in
// shaders/. lavapipe runs both sides of every branch, so code a scene cannot take still costs
// unless it is not there at all.

#include <string>

#include "kernels/scene_code.h"

namespace hexray::inline kernels {

std::string generateKernel(const SceneCode& code);

}  // namespace hexray::kernels
