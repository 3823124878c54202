#include "io/output_plan.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/output_error.h"
#include "io/output_target.h"
#include "io/standard_output.h"
#include "util/printable.h"

namespace hexray::inline io {
namespace {

namespace fs = std::filesystem;

// The directory itself if it exists, else its nearest existing ancestor, which must be a
// writable directory (the command creates the rest).
void requireCreatableDirectory(const std::string& option, const fs::path& path) {
    fs::path existing = path;
    std::error_code ignored;
    while (existing != "." && !fs::exists(fs::symlink_status(existing, ignored))) {
        existing = directoryOf(existing);
    }
    const std::string why = unwritableDirectoryReason(existing);
    if (!why.empty()) {
        throw OutputError(option + " " + printable(path.string()) + ": cannot create the directory: " + why);
    }
}

}  // namespace

void OutputPlan::addInput(const std::string& description, const std::string& path) {
    inputs_.emplace_back(description, path);
}

void OutputPlan::addFile(const std::string& option, const std::string& path) {
    outputs_.push_back({option, path, {}});
}

void OutputPlan::addDirectory(const std::string& option, const fs::path& path, Owns owns) {
    outputs_.push_back({option, path, std::move(owns)});
}

OutputPlan::Identity OutputPlan::identityOf(const fs::path& path) {
    fs::path existing = path.empty() ? fs::path(".") : path;
    fs::path below;
    struct stat status {};
    while (::stat(existing.c_str(), &status) != 0 && existing != ".") {
        below = existing.filename() / below;
        existing = directoryOf(existing);
    }
    return {status.st_dev, status.st_ino, below.lexically_normal().string()};
}

OutputPlan::Entry OutputPlan::fileEntry(const std::string& label, const std::string& path) {
    Entry entry;
    entry.label = label;
    if (namesStandardOutput(path)) {
        struct stat status {};
        ::fstat(standardOutputDescriptor(), &status);
        entry.identity = {status.st_dev, status.st_ino, ""};
        return entry;
    }
    const fs::path file = followSymlinks(path);
    entry.identity = identityOf(file);
    entry.directory = identityOf(directoryOf(file));
    entry.name = file.filename().string();
    return entry;
}

void OutputPlan::checkPair(const Entry& output, const Entry& other) {
    if (output.identity == other.identity) {
        const char* how = output.owns || other.owns ? "the same path as" : "the same file as";
        throw OutputConflict(output.label + ": " + how + " " + other.label);
    }
    if (output.owns && !other.name.empty() && other.directory == output.identity && output.owns(other.name)) {
        throw OutputConflict(output.label + ": would write over " + other.label);
    }
    if (other.owns && !output.name.empty() && output.directory == other.identity && other.owns(output.name)) {
        throw OutputConflict(output.label + ": a file that " + other.label + " also writes");
    }
}

void OutputPlan::checkWritable(const Output& output) {
    if (output.owns) {
        requireCreatableDirectory(output.option, output.path);
    } else {
        resolveOutputTarget(output.path.string());
    }
}

void OutputPlan::check() const {
    std::vector<Entry> outputs;
    for (const Output& output : outputs_) {
        const std::string label = output.option + " " + printable(output.path.string());
        if (output.owns) {
            Entry directory;
            directory.label = label;
            directory.identity = identityOf(output.path);
            directory.owns = output.owns;
            outputs.push_back(std::move(directory));
        } else {
            outputs.push_back(fileEntry(label, output.path.string()));
        }
    }
    for (const auto& [description, path] : inputs_) {
        if (::access(path.c_str(), F_OK) == 0) {
            const Entry input = fileEntry(description + " " + printable(path), path);
            for (const Entry& output : outputs) {
                checkPair(output, input);
            }
        }
    }
    for (std::size_t later = 1; later < outputs.size(); ++later) {
        for (std::size_t earlier = 0; earlier < later; ++earlier) {
            checkPair(outputs[later], outputs[earlier]);
        }
    }
    for (const Output& output : outputs_) {
        checkWritable(output);
    }
}

}  // namespace hexray::io
