#pragma once
// What a pixel *is*, as opposed to its colour: which node it shows, which checker cell, which
// lights reach it. Both renderers report it, so a comparison can count discrete (topology)
// disagreements separately from colour errors.

#include <cstdint>

#include "shader_interface.h"  // the encoding, shared with the shader

namespace hexray::inline image {

struct PixelClass {
    static constexpr std::uint32_t kBackground = gpu::BACKGROUND;
    static constexpr std::uint32_t kOddCheckerBit = gpu::ODD_CHECKER_BIT;       // checker-shaded, in a color2 cell
    static constexpr std::uint32_t kClassifiedLights = gpu::CLASSIFIED_LIGHTS;  // lights 0..30 have a bit each

    // Bit for "light `index` contributes to this pixel" (faces it and is not shadowed).
    static constexpr std::uint32_t litBit(std::uint32_t index) { return index < kClassifiedLights ? 2u << index : 0u; }

    std::uint32_t node = kBackground;  // index into Scene::nodes of the visible node
    std::uint32_t flags = 0;

    bool operator==(const PixelClass&) const = default;
};

// Which parts of a pixel's classification the CPU reference could not settle: each part whose
// decision came within roundoff of going the other way ("near-tied"). A comparison excuses a
// difference in those parts only; the others must still agree.
struct PixelAmbiguity {
    bool node = false;        // which node (or the background) the pixel shows
    std::uint32_t flags = 0;  // PixelClass::flags bits: the checker cell, each classified light
    // A near-tied decision the classification does not record: another sample's (the class
    // comes from the first), or a light beyond the classified ones. The colour may then differ
    // honestly even where the classes agree.
    bool colour = false;

    bool any() const { return node || flags != 0 || colour; }

    // Every part: a pixel where nothing can be held against the test render.
    static PixelAmbiguity everything() { return {true, ~0u, true}; }

    PixelAmbiguity& operator|=(const PixelAmbiguity& other) {
        node = node || other.node;
        flags |= other.flags;
        colour = colour || other.colour;
        return *this;
    }
    bool operator==(const PixelAmbiguity&) const = default;
};

}  // namespace hexray::image
