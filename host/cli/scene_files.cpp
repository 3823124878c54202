#include "cli/scene_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

bool hasJsonExtension(const fs::path& path) {
    const std::string extension = path.extension().string();
    return extension.size() == 5 && std::equal(extension.begin(), extension.end(), ".json", [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == b;
           });
}

// The scene files under `directory` (the one given: `root`), and an entry for each directory in
// it that cannot be read. Symlinks to directories are not followed, as `find` does not.
void collect(const fs::path& directory, const fs::path& root, std::vector<SceneFile>& found) {
    const auto failed = [&](const std::error_code& error) {
        const std::string name = directory == root ? directory.string() : fs::relative(directory, root).string();
        found.push_back({directory.string(), name, "cannot read the directory: " + error.message()});
    };
    std::error_code error;
    std::vector<fs::path> subdirectories;
    for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
         entry.increment(error)) {
        std::error_code ignored;
        if (entry->is_directory(ignored) && !entry->is_symlink(ignored)) {
            subdirectories.push_back(entry->path());
        } else if (entry->is_regular_file(ignored) && hasJsonExtension(entry->path()) &&
                   entry->path().filename() != kExpectationsFileName) {
            const fs::path name = fs::relative(entry->path(), root).replace_extension();
            found.push_back({entry->path().string(), name.string(), ""});
        }
    }
    if (error) {
        failed(error);
        return;
    }
    for (const fs::path& subdirectory : subdirectories) {
        collect(subdirectory, root, found);
    }
}

}  // namespace

std::vector<SceneFile> sceneFiles(const std::vector<std::string>& paths) {
    if (std::count(paths.begin(), paths.end(), kStandardInputPath) > 1) {
        throw SceneError("standard input (-) is named more than once: it holds one scene");
    }
    std::vector<SceneFile> files;
    for (const std::string& path : paths) {
        std::error_code error;
        if (!fs::is_directory(path, error)) {
            files.push_back({path, fs::path(path).stem().string(), ""});  // a missing file is reported when loaded
            continue;
        }
        std::vector<SceneFile> found;
        collect(path, path, found);
        if (found.empty()) {
            throw SceneError(printable(path) + ": no scene files (*.json) in this directory");
        }
        std::sort(found.begin(), found.end(), [](const SceneFile& a, const SceneFile& b) { return a.name < b.name; });
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

void requireReadable(const SceneFile& file) {
    if (!file.problem.empty()) {
        throw SceneError(printable(file.path) + ": " + file.problem);
    }
}

}  // namespace hexray::cli
