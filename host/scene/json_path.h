#pragma once
// Places in a JSON document as scene-file messages name them: nodes[3].geometry.radius,
// shaders["my ball"].color. Shared by the scene file's parser and its reader.

#include <cstddef>
#include <string>

namespace hexray::inline scene {

// Longer user strings are cut in messages, so a huge key or name cannot flood the terminal.
inline constexpr std::size_t kMaxShown = 40;

// JSON-quoted (control characters and quotes stay readable, DEL and C1 controls escaped as by
// util/printable.h) and cut to kMaxShown characters.
std::string quotedForMessage(const std::string& text);

// "camera" + "fov" -> camera.fov; a key like "my ball" becomes shaders["my ball"].
std::string childPath(const std::string& parent, const std::string& key);

// "nodes" + 3 -> nodes[3].
std::string elementPath(const std::string& parent, std::size_t index);

// The root's path is empty; messages call it (root).
std::string displayPath(const std::string& path);

}  // namespace hexray::scene
