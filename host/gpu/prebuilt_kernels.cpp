#include "gpu/prebuilt_kernels.h"

namespace {
// SPIR-V generated from shaders/render.comp at build time (see CMakeLists.txt).
#include "kRenderF32BvhSpv.h"
#include "kRenderF32NaiveBvhSpv.h"
#include "kRenderF32NaiveStorageSpv.h"
#include "kRenderF32StorageSpv.h"
#include "kRenderF64BvhSpv.h"
#include "kRenderF64StorageSpv.h"
}  // namespace

namespace hexray {

std::span<const std::uint32_t> dataDrivenKernel(FloatWidth width, Formulation formulation, bool bvh) {
    if (width == FloatWidth::F64) {
        return bvh ? std::span<const std::uint32_t>(kRenderF64BvhSpv) : kRenderF64StorageSpv;
    }
    if (formulation == Formulation::Textbook) {
        return bvh ? std::span<const std::uint32_t>(kRenderF32NaiveBvhSpv) : kRenderF32NaiveStorageSpv;
    }
    return bvh ? std::span<const std::uint32_t>(kRenderF32BvhSpv) : kRenderF32StorageSpv;
}

std::string dataDrivenKernelName(FloatWidth width, Formulation formulation, bool bvh) {
    std::string name = width == FloatWidth::F64 ? "render.comp f64" : "render.comp f32";
    name += formulation == Formulation::Textbook ? " textbook" : "";
    return name + (bvh ? " bvh" : " storage");
}

}  // namespace hexray
