#pragma once
// A GPU render against the CPU reference, whose near-ties are judged at the render's precision:
// what `hexray compare` does, on whole images.

#include "compare/compare.h"
#include "precision/decision_roundoff.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"

namespace hexray::test {

inline RenderComparison compareWithReference(const Scene& scene, const GpuRenderResult& gpu) {
    const CpuRender cpu = renderOnCpu(scene, 0, Acceleration::Auto, false, decisionRoundoff(gpu.precision));
    return compareRenders(cpu.image, cpu.classes, cpu.ambiguity, gpu.image, gpu.classes, scene.image.encoding);
}

}  // namespace hexray::test
