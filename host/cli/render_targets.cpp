#include "cli/render_targets.h"

#include <filesystem>
#include <map>

#include "cli/scene_files.h"
#include "io/output_error.h"
#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

std::string defaultName(const std::string& scenePath, const std::optional<Strip>& strip) {
    std::string name = fs::path(scenePath).stem().string();
    if (strip) {
        name += ".strip-" + std::to_string(strip->index) + "-of-" + std::to_string(strip->count);
    }
    return name + ".png";
}

// Whether `-o` names a directory to put the images in: an existing one, or a path ending in '/'.
bool namesDirectory(const std::string& output) {
    std::error_code ignored;
    return !output.empty() && (output.back() == '/' || fs::is_directory(output, ignored));
}

// The directory several scenes go into, checked.
fs::path outputDirectory(const std::string& output, std::size_t scenes) {
    std::error_code ignored;
    if (output.empty()) {
        return "";
    }
    if (!namesDirectory(output)) {
        throw SceneError("-o " + printable(output) + ": " + std::to_string(scenes) +
                         " scenes are rendered into a directory, and this is not one");
    }
    if (!fs::is_directory(output, ignored)) {
        throw OutputError("-o " + printable(output) + ": no such directory (the scenes' images go into it)");
    }
    return output;
}

}  // namespace

std::vector<RenderTarget> renderTargets(const RenderOptions& options) {
    const std::vector<SceneFile> scenes = sceneFiles(options.scenePaths);
    const bool single = scenes.size() == 1 && !namesDirectory(options.outputPath);
    if (single && !options.outputPath.empty()) {
        return {{scenes[0].path, options.outputPath, imageFormatFor(options.outputPath), scenes[0].problem}};
    }
    const fs::path directory = outputDirectory(options.outputPath, scenes.size());
    std::vector<RenderTarget> targets;
    std::map<std::string, std::string> sceneByOutput;
    for (const SceneFile& scene : scenes) {
        if (!scene.problem.empty()) {
            targets.push_back({scene.path, "", std::nullopt, scene.problem});
            continue;
        }
        if (scene.path == kStandardInputPath) {
            throw SceneError(
                "the scene comes from standard input (-), so there is no file name to name its image after: "
                "give -o (e.g. -o image.png, or -o - for PNG on standard output)");
        }
        const std::string output = (directory / defaultName(scene.path, options.strip)).string();
        const auto [earlier, added] = sceneByOutput.emplace(fs::path(output).lexically_normal().string(), scene.path);
        if (!added) {
            throw SceneError("scenes " + printable(earlier->second) + " and " + printable(scene.path) +
                             " would both be written to " + printable(output) +
                             " (the image is named after the scene file): render them separately");
        }
        targets.push_back({scene.path, output, ImageFormat::Png, ""});
    }
    return targets;
}

}  // namespace hexray::cli
