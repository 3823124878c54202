#pragma once
// The kernel generator's vocabulary: what a kernel written for one scene's structure does for each
// node and each light (decided by the render plan, written by kernel_generator.h).

#include <cstdint>
#include <vector>

#include "precision/arithmetic.h"

namespace hexray::inline kernels {

// How a camera ray meets one sphere (generated kernels).
enum class SphereTest {
    Robust,    // Hearn-Baker discriminant and the stable root pair; normal from the chord
    Fast,      // b^2 - power with the host's power of the eye; normal from o + t d
    Textbook,  // b^2 - 4ac, as f32-naive does everywhere
};

// What a generated kernel does for one node.
struct NodeCode {
    std::uint32_t geometry = 0;                  // gpu::GEOMETRY_*
    std::uint32_t shader = 0;                    // gpu::SHADER_*
    SphereTest sphereTest = SphereTest::Robust;  // spheres only
    // Spheres: the eye is outside, so a point the camera sees on it faces away from the sphere
    // and the sphere cannot shadow it (convexity); its shadow rays skip it.
    bool cameraOutside = false;
    // Whether camera rays test it: false in a tile class none of whose rays can hit it
    // (tile_classes.h); its values may still serve shadow tests.
    bool cameraTested = true;
};

// One shadow test a light needs (generated kernels): whether `node` lies strictly between a lit
// point and the light. Robust kernels test spheres from the light, which is the same origin for
// every pixel, so the test's conditioning is known here (and the host computes the light's power
// with respect to the sphere in double); planes by the sides of the segment's ends.
struct ShadowTest {
    std::uint32_t node = 0;
    SphereTest sphereTest = SphereTest::Robust;  // spheres only
    bool lightOutside = true;                    // spheres: the light lies outside the sphere
    // Spheres: it holds the eye and not the light (sphereHidesLight), so it blocks the light from
    // every visible point: decided without arithmetic, and the light's only test.
    bool hidesLight = false;
    // False in a tile class no point of which it can shadow (tile_classes.h): the kernel leaves the
    // test out, while its values stay among the specialization constants, the same for every class.
    bool tested = true;
};

// A kernel written for one scene's structure (host/kernels/kernel_generator.h): the node tests
// unrolled in order, only the shaders, lights and shadow tests the scene uses. The scene's values
// reach it as specialization constants (host/kernels/scene_constants.h), which lavapipe compiles in as
// literals: scenes of the same structure share the SPIR-V, and the driver builds a pipeline per
// scene.
struct SceneCode {
    std::vector<NodeCode> nodes;
    // Per light, the nodes that may shadow it: a plane with the eye and the light strictly on one
    // side cannot come between a visible point and the light.
    std::vector<std::vector<ShadowTest>> shadowTests;
    FloatWidth width = FloatWidth::F32;
    Formulation formulation = Formulation::Robust;
    bool eyeAtOrigin = true;  // camera-relative placement: camera rays start at exactly 0
    bool tileList = false;    // a tile class's kernel: it renders the tiles listed for it
    // f32-certified: every decision is checked against CERTAINTY_BOUND (certified.glsl), and a pixel
    // with one in doubt is flagged for the f64 pass.
    bool certified = false;
    // f32-certified's f64 pass: it renders the pixels listed for it, each written at its place in the list.
    bool pixelList = false;
    // The scene's values read from a storage buffer (SCENE_VALUE_BINDING, the same bytes in the same
    // order) instead of specialization constants: a little slower to run, but one pipeline serves
    // every scene of this structure, so an edited value renders without a new one (`hexray watch`).
    bool valuesInBuffer = false;
};

}  // namespace hexray::kernels
