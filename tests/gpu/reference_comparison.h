#pragma once
// A GPU render against the CPU reference, whose near-ties are judged at the render's precision:
// what `hexray compare` does, on whole images.

#include <algorithm>
#include <string>

#include "compare/compare.h"
#include "precision/decision_roundoff.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"

namespace hexray::test {

inline RenderComparison compareWithReference(const Scene& scene, const GpuRenderResult& gpu) {
    const CpuRender cpu = renderOnCpu(scene, 0, Acceleration::Auto, false, decisionRoundoff(gpu.precision));
    return compareRenders(cpu.image, cpu.classes, cpu.ambiguity, gpu.image, gpu.classes, scene.image.encoding);
}

// A gtest-safe name for a precision: "f32", "f64", "f32_certified".
inline std::string precisionTestName(Precision precision) {
    std::string name(precisionName(precision));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

}  // namespace hexray::test
