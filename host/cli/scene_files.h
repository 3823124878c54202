#pragma once
// The scene files a command names: files as given, directories searched for *.json.

#include <string>
#include <vector>

namespace hexray::cli {

// Not a scene: `hexray compare`'s expectations for the scenes beside it (cli/compare_expectations.h).
inline constexpr const char* kExpectationsFileName = "hexray-expectations.json";

struct SceneFile {
    std::string path;
    std::string name;     // for tables: the path under the directory given, without .json
    std::string problem;  // a directory that could not be searched: why (the entry then fails)
};

// The scene files named, with directories expanded to the files under them whose names end in
// .json, in any case, except the expectations file (sorted by name). A directory (given, or found inside one) that cannot be
// read becomes an entry with its problem, so that the command reports it as a failed scene and
// goes on with the others. Throws SceneError for a directory that holds no scene file and no
// such problem.
std::vector<SceneFile> sceneFiles(const std::vector<std::string>& paths);

// Throws SceneError "<path>: <problem>" for an entry with a problem.
void requireReadable(const SceneFile& file);

}  // namespace hexray::cli
