#pragma once
// Every path a command reads and writes, checked together before the command does any work: no
// output is the same file as an input or as another output, and each output can be written (its
// directory exists and is writable). Files are compared by device and inode, not by name, so
// hard links, symlinks and `dir/../name` are seen through; a path that does not exist yet is
// compared by its nearest existing directory's device and inode and the rest of the path.

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexray::inline io {

// An output that would destroy an input or another output of the same command. Exit code 2.
class OutputConflict : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class OutputPlan {
public:
    // Which file names in an output directory the command may write or remove.
    using Owns = std::function<bool(const std::string& name)>;

    // A file the command reads, e.g. ("the scene", path). One that does not exist is left to the
    // command to report.
    void addInput(const std::string& description, const std::string& path);
    // A file the command writes; `option` names it in messages ("-o", "--csv").
    void addFile(const std::string& option, const std::string& path);
    // A directory the command creates if needed and writes the files `owns` names into.
    void addDirectory(const std::string& option, const std::filesystem::path& path, Owns owns);

    // Throws OutputConflict for an output that is an input or another output (checked first),
    // OutputError for an output that cannot be written.
    void check() const;

private:
    struct Identity {
        dev_t device = 0;
        ino_t inode = 0;
        std::string below;  // the part of the path that does not exist yet
        bool operator==(const Identity&) const = default;
    };
    struct Entry {
        std::string label;  // "-o out.png", "the scene my.json"
        Identity identity;
        Identity directory;  // files: the directory the file is in
        std::string name;    // files: its name there
        Owns owns;           // output directories only
    };
    struct Output {
        std::string option;
        std::filesystem::path path;
        Owns owns;  // empty for a file
    };

    static Identity identityOf(const std::filesystem::path& path);
    static Entry fileEntry(const std::string& label, const std::string& path);
    static void checkPair(const Entry& output, const Entry& other);
    static void checkWritable(const Output& output);

    std::vector<std::pair<std::string, std::string>> inputs_;
    std::vector<Output> outputs_;
};

}  // namespace hexray::io
