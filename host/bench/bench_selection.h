#pragma once
// Which rows `hexray bench` measures (--backends): by the name of a kind of row, or of a group
// of them. A bench at scale chooses the few rows it needs, leaving out the textbook kernel and
// the CPU reference, which test every node for every ray.

#include <set>
#include <string>
#include <vector>

namespace hexray::inline bench {

enum class BenchRowKind {
    GpuF32,            // the renderer in f32, culled and whole (the curve: whole)
    GpuF64,            // the renderer in f64, culled and whole, where the device has float64
    GpuF32Naive,       // the renderer's textbook f32 formulation
    GpuF32Certified,   // the renderer in f32-certified, culled and whole, where the device has float64
    HandWritten,       // the lecture demo's hand-written kernel, on the lecture demo
    Cpu,               // the CPU reference, and the converged reference of the sampling error
    Embree,            // Embree at its best: the widest packets, shading in float
    EmbreeF64Packets,  // Embree's 8-ray packets, shading in double through the CPU reference's code
    EmbreeF64Single,   // Embree one ray at a time, shading in double as above
};

using BenchSelection = std::set<BenchRowKind>;

struct BenchRowName {
    std::string name;
    BenchSelection kinds;
};

// Every name --backends takes, groups ("gpu", "all") included, in the order the help lists them.
const std::vector<BenchRowName>& benchRowNames();

// The names of the rows measured when --backends is not given.
const std::vector<std::string>& defaultBenchRowNames();

// The rows `names` choose (each one of benchRowNames(); the command line has checked them); the
// default's when there are none.
BenchSelection selectBenchRows(const std::vector<std::string>& names);

}  // namespace hexray::bench
