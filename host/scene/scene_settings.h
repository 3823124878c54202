#pragma once
// `--set PATH=VALUE`: changes to a scene file's JSON made before the scene is read from it, as
// Mitsuba's -D, so one file serves several renders (--set camera.fov=60, --set
// nodes[1].geometry.radius=1.5, --set 'shaders["my ball"].color="#e63946"'). PATH is written as
// the loader's messages write places; VALUE is JSON, or else taken as a string.

#include <string>
#include <vector>

namespace hexray::inline scene {

// `text` (a scene file's, comments allowed) with each setting applied in order, as plain JSON.
// Throws SceneError naming `source` for text that is not JSON (line:column, or a duplicate key
// at its path), and naming the option ("--set X=Y: ...") for a setting that is not PATH=VALUE or
// whose path does not lead into the document: through an array's elements or an object's keys,
// where only the last key may be new.
std::string withSettings(const std::string& text, const std::string& source, const std::vector<std::string>& settings);

}  // namespace hexray::scene
