#pragma once
// A kernel a plan runs, generated or prebuilt.

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "kernels/scene_code.h"

namespace hexray::inline kernels {

// The program a plan runs: GLSL written for the scene (compiled at run time and cached), or
// SPIR-V built with hexray (the data-driven kernels, or a caller's own, such as the bench's
// yardstick). The SPIR-V must outlive the plan.
struct Kernel {
    std::string name;                       // for messages and the pipeline cache
    std::shared_ptr<const SceneCode> code;  // a generated kernel: what to generate
    std::span<const std::uint32_t> spirv;   // else: the program itself
};

}  // namespace hexray::kernels
