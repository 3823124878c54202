#pragma once
// Reads scene files (UTF-8 JSON, comments allowed) into the scene model, rejecting anything the
// renderers cannot use. Messages name the source with its control characters escaped
// (util/printable.h).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace hexray::inline scene {

// A rejected scene. what() names the source, the place (line:column for syntax errors,
// the JSON path such as nodes[3].geometry.radius otherwise) and the reason.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Told, about every MiB of a large file, how many bytes the parser has read of how many.
using ParseProgress = std::function<void(std::size_t parsedBytes, std::size_t totalBytes)>;

// A scene path of "-" is standard input, which messages call <stdin>.
inline constexpr const char* kStandardInputPath = "-";
std::string sceneSourceName(const std::string& path);

Scene loadSceneFile(const std::filesystem::path& path);
// loadSceneFile in two steps, for a caller that wants the text too or the parse's progress.
// Reads standard input for "-".
std::string readSceneFile(const std::filesystem::path& path);
Scene parseScene(const std::string& text, const std::string& sourceName, const ParseProgress& progress = {});

// Replaces the image size (e.g. from the command line), with the same checks as the file's.
// `source` names where the numbers came from, for the message.
void overrideImageSize(Scene& scene, std::int64_t width, std::int64_t height, const std::string& source);

// Replaces the samples per pixel, with the same check as the file's "spp".
void overrideSamplesPerPixel(Scene& scene, std::int64_t samples, const std::string& source);

}  // namespace hexray::scene
