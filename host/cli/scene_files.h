#pragma once
// The scene files a command names: files as given, directories searched for *.json.

#include <string>
#include <vector>

namespace hexray::cli {

struct SceneFile {
    std::string path;
    std::string name;  // for tables: the path under the directory given, without .json
};

// The scene files named, with directories expanded to the *.json files under them (sorted by
// name). Throws SceneError for a directory that cannot be read or holds no scene file.
std::vector<SceneFile> sceneFiles(const std::vector<std::string>& paths);

}  // namespace hexray::cli
