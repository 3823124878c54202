#pragma once
// The values a generated kernel takes as specialization constants (after the ones every kernel
// takes, see shader_interface.h), in id order: each node's geometry and shader parameters, each
// light's position and power, the ambient light and background, and for robust shadow tests the light's power
// with respect to the sphere. lavapipe compiles a specialization constant in as a literal, where a
// uniform-buffer value costs a load (about a fifth of the demo scene's frame). One list, read by
// both the generator (declarations) and the renderer (values), so the two cannot disagree.

#include <cstdint>
#include <string>
#include <vector>

#include "kernels/scene_code.h"

namespace hexray::inline kernels {

struct SceneConstant {
    enum class Field {
        Geometry,        // node: plane .x height; sphere .xyzw centre and radius
        EyePower,        // sphere node: the eye's power |eye - centre|^2 - r^2
        Color1,          // node .rgb
        Color2,          // checker node .rgb
        Checker,         // checker node: size, the eye's cell fraction (x, z), parity of its cells
        LightPosition,   // light .xyz
        LightPower,      // light .rgb: colour x intensity
        LightNodePower,  // light and sphere node: the light's power with respect to the sphere
        Ambient,         // .rgb
        Background,      // .rgb
        CertaintyBound,  // f32-certified: float32's error per unit of a decision's scale (certified.glsl)
    };
    Field field;
    std::uint32_t index = 0;  // the node, or the light
    std::uint32_t node = 0;   // LightNodePower: the sphere
    std::uint32_t components = 1;
    bool real = false;  // in the kernel's arithmetic (positions, lengths); else float (colours)
    std::string name;   // the GLSL constant; its components are NAME_0, NAME_1, ...
};

std::vector<SceneConstant> sceneConstants(const SceneCode& code);

}  // namespace hexray::kernels
