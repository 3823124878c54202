#pragma once
// The data-driven kernel (shaders/render.comp), compiled to SPIR-V at build time and embedded in
// hexray, for scenes too large for a generated kernel.

#include <cstdint>
#include <span>
#include <string>

#include "precision/arithmetic.h"

namespace hexray::inline kernels {

std::span<const std::uint32_t> dataDrivenKernel(FloatWidth width, Formulation formulation, bool candidates);
std::string dataDrivenKernelName(FloatWidth width, Formulation formulation, bool candidates);

}  // namespace hexray::kernels
