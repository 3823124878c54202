#pragma once
// SPIR-V checked by SPIRV-Tools' validator before hexray hands it to a driver that did not make
// it (the kernel cache's files): the rules of the environment hexray compiles for, Vulkan 1.1
// with SPIR-V 1.3 (shader_compiler.h), and the validator's universal limits, so that an id bound
// of 0xFFFFFFFF, among others, is refused rather than allocated.

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace hexray::inline kernels {

// Nothing when `spirv` is valid; else the validator's first message. Thread-safe.
std::optional<std::string> spirvValidationProblem(std::span<const std::uint32_t> spirv);

}  // namespace hexray::kernels
