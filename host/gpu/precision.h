#pragma once
// Which arithmetic the shader uses, and how hexray picks the cheapest one a scene needs.

#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace hexray {

enum class Precision {
    Auto,      // chosen per scene by choosePrecision
    F32Naive,  // the textbook formulation in world coordinates: kept to show what the rest buys
    F32,       // float, camera-relative, cancellation-free intersection, error-bound offsets
    F64,       // the same in double (needs the device's shaderFloat64)
};

std::string_view precisionName(Precision precision);  // "auto", "f32-naive", "f32", "f64"
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

// F32 when the conditioning ratio is within kFloat32ConditioningLimit, else F64 (or F32 when
// the device has no float64, which the caller reports).
Precision choosePrecision(const Scene& scene, bool deviceHasFloat64);

}  // namespace hexray
