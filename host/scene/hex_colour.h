#pragma once
// "#rrggbb" colours in scene files mean what they mean in CSS: sRGB, turned into the linear
// values the renderers work in when the file is loaded. ([r, g, b] arrays are linear as given.)

#include <optional>
#include <string>

#include "scene/scene.h"

namespace hexray::inline scene {

// The sRGB transfer function undone (IEC 61966-2-1), for a component in [0, 1].
double srgbToLinear(double encoded);

// "#1a2433" (either case) as linear RGB; none if `text` is not of that form.
std::optional<Color> parseHexColour(const std::string& text);

}  // namespace hexray::scene
