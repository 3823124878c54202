#pragma once
// The fixture the CLI tests share: runs the real hexray executable in a fresh directory and
// captures its exit code, stdout and stderr.

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/temporary_directory_test.h"
#include "support/test_paths.h"

namespace hexray::test {

namespace fs = std::filesystem;

struct RunResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

class CliTest : public TemporaryDirectoryTest {
protected:

    // Runs `hexray ARGS` in the test's directory; `environment` is prefixed to the command.
    RunResult hexray(const std::string& arguments, const std::string& environment = "") const {
        const fs::path out = dir_ / "stdout.txt";
        const fs::path err = dir_ / "stderr.txt";
        const std::string command = "cd '" + dir_.string() + "' && " + environment + " '" HEXRAY_EXECUTABLE "' " +
                                    arguments + " >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
        const int status = std::system(command.c_str());
        RunResult result;
        result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        result.out = readFile(out);
        result.err = readFile(err);
        return result;
    }

    fs::path writeScene(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }

    // Files the command created besides its captured output.
    std::vector<std::string> createdFiles() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            const std::string name = entry.path().filename().string();
            if (name != "stdout.txt" && name != "stderr.txt" && entry.path().extension() != ".json") {
                names.push_back(name);
            }
        }
        return names;
    }

    static std::string scene(const std::string& name) { return "'" + test::sourcePath("scenes/" + name).string() + "'"; }
};

}  // namespace hexray::test
