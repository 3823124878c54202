#include "kernels/prebuilt_kernels.h"

namespace {
// SPIR-V generated from shaders/render.comp at build time (see CMakeLists.txt).
#include "kRenderF32CandidatesSpv.h"
#include "kRenderF32NaiveCandidatesSpv.h"
#include "kRenderF32NaiveStorageSpv.h"
#include "kRenderF32StorageSpv.h"
#include "kRenderF64CandidatesSpv.h"
#include "kRenderF64StorageSpv.h"
}  // namespace

namespace hexray::inline kernels {

std::span<const std::uint32_t> dataDrivenKernel(FloatWidth width, Formulation formulation, bool candidates) {
    if (width == FloatWidth::F64) {
        return candidates ? std::span<const std::uint32_t>(kRenderF64CandidatesSpv) : kRenderF64StorageSpv;
    }
    if (formulation == Formulation::Textbook) {
        return candidates ? std::span<const std::uint32_t>(kRenderF32NaiveCandidatesSpv) : kRenderF32NaiveStorageSpv;
    }
    return candidates ? std::span<const std::uint32_t>(kRenderF32CandidatesSpv) : kRenderF32StorageSpv;
}

std::string dataDrivenKernelName(FloatWidth width, Formulation formulation, bool candidates) {
    std::string name = width == FloatWidth::F64 ? "render.comp f64" : "render.comp f32";
    name += formulation == Formulation::Textbook ? " textbook" : "";
    return name + (candidates ? " candidates" : " storage");
}

}  // namespace hexray::kernels
