#pragma once
// Which arithmetic the shader uses, and how hexray picks the cheapest one a scene needs.

#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace hexray::inline precision {

enum class Precision {
    Auto,      // chosen per scene by choosePrecision
    F32Naive,  // the textbook formulation in world coordinates: kept to show what the rest buys
    F32,       // float, camera-relative, cancellation-free intersection, error-bound offsets
    F64,       // the same in double (needs the device's shaderFloat64)
    // f32 whose every decision is checked against a bound on its error; a pixel with a decision in
    // doubt is rendered again in f64 (needs shaderFloat64): f64's decisions at about f32's cost
    F32Certified,
};

std::string_view precisionName(Precision precision);  // "auto", "f32-naive", "f32", "f64", "f32-certified"
std::optional<Precision> parsePrecision(std::string_view name);

// How hard a scene is on float32, after the host's camera-relative rebase: the largest
// distance the shader works with against the smallest feature it must resolve.
struct Conditioning {
    double largestDistance = 0;  // camera to the farthest sphere surface, plane or light
    double smallestFeature = 0;  // smallest sphere radius, eye-to-sphere clearance or plane checker square
    double ratio() const { return smallestFeature > 0 ? largestDistance / smallestFeature : 0; }
};

Conditioning estimateConditioning(const Scene& scene);

// float32 carries about 7 digits. Positions are good to about 6e-8 of the largest distance;
// asking that this stay below 1e-3 of the smallest feature (a thousandth of a sphere's radius
// or of a checker square) allows a ratio of about 1.7e4; 1e4 keeps a margin.
inline constexpr double kFloat32ConditioningLimit = 1e4;

// The lengths the shader's arithmetic meets after the camera-relative rebase (sphere radii, the
// eye's distances to each sphere's near and far side, to each plane and light, plane checker
// squares, and for each light the length sqrt(intensity * brightest colour component), whose square
// is its uploaded power), the smallest and the largest nonzero one.
struct MagnitudeRange {
    double smallest = 0;  // 0 when the scene has no nonzero length
    double largest = 0;
    double ratio() const { return smallest > 0 ? largest / smallest : 1.0; }
};

MagnitudeRange sceneMagnitudes(const Scene& scene);

// Placed around the geometric middle of the range (gpu_scene.h), every length within 2^50 of it
// keeps its square, and a product of a few such, a normal float32 (2^-126 to 2^128).
inline constexpr double kFloat32MagnitudeRatio = 0x1p100;

// Why float32 cannot hold the scene's lengths (their ratio exceeds kFloat32MagnitudeRatio), or
// nothing. float64 holds every scene the loader accepts (scene.h: ratios below about 2^700).
std::optional<std::string> float32RangeProblem(const Scene& scene);

// F32 when the conditioning ratio is within kFloat32ConditioningLimit and float32 holds the
// scene's lengths, else F64 (or F32 when the device has no float64, which the caller reports).
Precision choosePrecision(const Scene& scene, bool deviceHasFloat64);

}  // namespace hexray::precision
