#pragma once
// The fixture the CLI tests share: runs the real hexray executable in a fresh directory and
// captures its exit code, stdout and stderr.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

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

// The executable under test: build/hexray, or the one HEXRAY_UNDER_TEST names (ci/sanitize.sh runs
// these tests against its ASan + UBSan build of hexray).
inline std::string hexrayExecutable() {
    const char* underTest = std::getenv("HEXRAY_UNDER_TEST");
    return underTest != nullptr && *underTest != '\0' ? underTest : HEXRAY_EXECUTABLE;
}

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
        return shell(environment + " \"$HEXRAY\" " + arguments);
    }

    // Runs a shell script in the test's directory, with $HEXRAY naming the executable; its
    // exit code is the script's.
    RunResult shell(const std::string& script) const {
        const fs::path out = dir_ / "stdout.txt";
        const fs::path err = dir_ / "stderr.txt";
        const std::string command = "cd '" + dir_.string() + "' && HEXRAY='" + hexrayExecutable() + "' && { " + script +
                                    "\n} >'" + out.string() + "' 2>'" + err.string() + "' </dev/null";
        const int status = std::system(command.c_str());
        RunResult result;
        result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        result.out = readFile(out);
        result.err = readFile(err);
        return result;
    }

    // Checks a --json document (a path in the test's directory, or absolute) against
    // docs/schemas/hexray-results.schema.json: exit code 0 and no output when it is valid.
    RunResult validateJson(const std::string& document) const {
        return shell("/usr/bin/python3 '" + sourcePath("tests/cli/validate_json.py").string() + "' '" +
                     sourcePath("docs/schemas/hexray-results.schema.json").string() + "' '" + document + "'");
    }

    // Starts hexray in the test's directory with every signal at its default action (a shell's
    // background job would ignore SIGINT and SIGQUIT) and `environment` ("NAME=value") added to
    // this process's; stdout and stderr go to the usual files.
    pid_t start(const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {}) const {
        std::vector<std::string> words = {hexrayExecutable()};
        words.insert(words.end(), arguments.begin(), arguments.end());
        std::vector<char*> argv;
        for (std::string& word : words) {
            argv.push_back(word.data());
        }
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addchdir_np(&actions, dir_.c_str());
        posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&actions, 1, "stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&actions, 2, "stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawnattr_t attributes;
        posix_spawnattr_init(&attributes);
        sigset_t all;
        sigfillset(&all);
        sigset_t none;
        sigemptyset(&none);
        posix_spawnattr_setsigdefault(&attributes, &all);
        posix_spawnattr_setsigmask(&attributes, &none);
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
        pid_t pid = -1;
        std::vector<std::string> variables(environment);
        for (char** variable = environ; *variable; ++variable) {
            variables.emplace_back(*variable);
        }
        std::vector<char*> envp;
        for (std::string& variable : variables) {
            envp.push_back(variable.data());
        }
        envp.push_back(nullptr);
        const int error = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), envp.data());
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
        return error == 0 ? pid : -1;
    }

    static std::vector<std::string> entriesStartingWith(const fs::path& directory, const std::string& prefix) {
        std::vector<std::string> names;
        std::error_code error;
        for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
             entry.increment(error)) {
            const std::string name = entry->path().filename().string();
            if (name.rfind(prefix, 0) == 0) {
                names.push_back(name);
            }
        }
        return names;
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
        std::sort(names.begin(), names.end());
        return names;
    }

    static std::string scene(const std::string& name) {
        return "'" + test::sourcePath("scenes/" + name).string() + "'";
    }
};

}  // namespace hexray::test
