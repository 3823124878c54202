#include "cli/scene_files.h"

#include <algorithm>
#include <filesystem>

#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::cli {

namespace fs = std::filesystem;

std::vector<SceneFile> sceneFiles(const std::vector<std::string>& paths) {
    std::vector<SceneFile> files;
    for (const std::string& path : paths) {
        std::error_code error;
        if (!fs::is_directory(path, error)) {
            files.push_back({path, fs::path(path).stem().string()});  // a missing file is reported when loaded
            continue;
        }
        std::vector<SceneFile> found;
        for (auto entry = fs::recursive_directory_iterator(path, error); !error && entry != fs::end(entry);
             entry.increment(error)) {
            if (entry->is_regular_file() && entry->path().extension() == ".json") {
                found.push_back({entry->path().string(),
                                 fs::relative(entry->path(), path).replace_extension().string()});
            }
        }
        if (error) {
            throw SceneError(printable(path) + ": cannot read the directory: " + error.message());
        }
        if (found.empty()) {
            throw SceneError(printable(path) + ": no scene files (*.json) in this directory");
        }
        std::sort(found.begin(), found.end(), [](const SceneFile& a, const SceneFile& b) { return a.name < b.name; });
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

}  // namespace hexray::cli
