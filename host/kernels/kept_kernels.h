#pragma once
// How many compiled kernels one renderer keeps in memory. A process that renders many scenes
// (`hexray render A.json B.json ...`) would otherwise keep every scene's pipeline (1-2 MB each on
// lavapipe) and every generated kernel's SPIR-V: its memory would grow with the number of scenes.
// Past these bounds the least recently used go; a later scene that needs one again finds its
// SPIR-V in the disk cache (kernel_cache.h) and the driver's compile in Mesa's.

#include <cstddef>

namespace hexray::inline kernels {

// Pipelines (a kernel with its specialization: a generated kernel's are the scene's values, so an
// animation makes one per frame). One render holds all of its tile classes' at once, so this
// must exceed their maximum (render_plan.cpp checks it).
inline constexpr std::size_t kKeptPipelines = 16;

// Generated kernels' SPIR-V, by source (the data-driven kernels are built in and always there).
inline constexpr std::size_t kKeptGeneratedKernels = 16;

// The bounds one renderer keeps to: these by default; more for a caller that knows it cycles
// through more kernels than that (the bench's interleaved configurations).
struct KeptKernels {
    std::size_t pipelines = kKeptPipelines;
    std::size_t generatedKernels = kKeptGeneratedKernels;
};

}  // namespace hexray::kernels
