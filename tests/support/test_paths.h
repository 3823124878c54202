#pragma once
// Where the tests find the repository's files.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace hexray::test {

inline std::filesystem::path sourcePath(const std::string& relative) {
    return std::filesystem::path(HEXRAY_SOURCE_DIR) / relative;
}

// Every shipped scene (scenes/**/*.json but compare's expectations file), sorted so test names are stable.
inline std::vector<std::filesystem::path> shippedScenes() {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(sourcePath("scenes"))) {
        if (entry.is_regular_file() && entry.path().extension() == ".json" &&
            entry.path().filename() != "hexray-expectations.json") {
            scenes.push_back(entry.path());
        }
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

// A gtest-safe name for a scene: its path under scenes/ with separators and dashes as '_'.
inline std::string sceneTestName(const std::filesystem::path& scene) {
    std::string name = std::filesystem::relative(scene, sourcePath("scenes")).replace_extension().string();
    std::replace_if(
        name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

}  // namespace hexray::test
