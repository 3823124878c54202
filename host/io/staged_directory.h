#pragma once
// A set of files written into a hidden staging directory inside their target directory and moved
// into place together, so the target holds either the earlier set or the whole new one. The
// target (and any missing parents) is created if needed; a staging directory that a killed
// process left behind is removed (stale_temporaries.h). Destroyed before finish() (a failure, an
// exception) or ended by a catchable signal, it removes the staging directory and the directories
// it created, and leaves the target as it was. Moves replace a symlink at the target's name,
// never follow it. Used by `--aov DIR` (image/aov.h) and `compare --report DIR`.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hexray::inline io {

class RemovedOnSignal;

class StagedDirectory {
public:
    // `stagingPrefix` names the staging directory (temporary_names.h); `what` names the target in
    // errors ("the AOV directory"). Throws OutputError when either cannot be created.
    StagedDirectory(const std::filesystem::path& directory, std::string_view stagingPrefix, const std::string& what);
    ~StagedDirectory();
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    const std::filesystem::path& directory() const { return directory_; }
    const std::filesystem::path& staging() const { return staging_; }

    // Moves staging()/name to `destination` (in the target directory or below it). Throws OutputError.
    void moveIntoPlace(const std::string& name, const std::filesystem::path& destination) const;

    // Removes the files in `directory` that `isOwned` accepts and `kept` does not name: an earlier
    // set's that this one did not replace. Symlinks are removed, never followed. Throws OutputError.
    static void removeOthers(const std::filesystem::path& directory,
                             const std::function<bool(const std::string&)>& isOwned,
                             const std::vector<std::string>& kept);

    // Every file is in place: the target directory stays, the staging directory goes.
    void finish();

private:
    void createDirectory(const std::string& what);
    void discard();

    std::filesystem::path directory_;
    std::vector<std::filesystem::path> created_;  // directories this set created, deepest first
    std::filesystem::path staging_;               // empty once finished or discarded
    int stagingLock_ = -1;                        // holds the staging directory as a live run's
    std::unique_ptr<RemovedOnSignal> removal_;
};

}  // namespace hexray::io
