#pragma once
// What a pixel *is*, as opposed to its colour: which node it shows, which checker cell, which
// lights reach it. Both renderers report it, so a comparison can count discrete (topology)
// disagreements separately from colour errors.

#include <cstdint>

#include "shader_interface.h"  // the encoding, shared with the shader

namespace hexray {

struct PixelClass {
    static constexpr std::uint32_t kBackground = gpu::BACKGROUND;
    static constexpr std::uint32_t kOddCheckerBit = gpu::ODD_CHECKER_BIT;  // checker-shaded, in a color2 cell
    static constexpr std::uint32_t kClassifiedLights = gpu::CLASSIFIED_LIGHTS;  // lights 0..30 have a bit each

    // Bit for "light `index` contributes to this pixel" (faces it and is not shadowed).
    static constexpr std::uint32_t litBit(std::uint32_t index) {
        return index < kClassifiedLights ? 2u << index : 0u;
    }

    std::uint32_t node = kBackground;  // index into Scene::nodes of the visible node
    std::uint32_t flags = 0;

    bool operator==(const PixelClass&) const = default;
};

}  // namespace hexray
