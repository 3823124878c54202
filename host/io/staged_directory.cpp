#include "io/staged_directory.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "io/output_error.h"
#include "io/remove_without_following.h"
#include "io/removed_on_signal.h"
#include "io/stale_temporaries.h"
#include "io/temporary_names.h"
#include "util/printable.h"

namespace hexray::inline io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void failStaging(const fs::path& path, const std::string& what, const std::string& why) {
    throw OutputError(printable(path.string()) + ": " + what + ": " + why);
}

}  // namespace

StagedDirectory::StagedDirectory(const fs::path& directory, std::string_view stagingPrefix, const std::string& what)
    : directory_(directory) {
    try {
        createDirectory(what);
        removeStaleTemporaries(directory_);
        // Inside the target, so that moving a file into place is a rename within one file system.
        RegisteredTemporary staging = createTemporary((directory_ / std::string(stagingPrefix)).string() + "XXXXXX",
                                                      RemovedOnSignal::Kind::Directory);
        if (staging.descriptor < 0) {
            failStaging(directory_, "cannot create a staging directory", std::generic_category().message(errno));
        }
        staging_ = staging.path;
        removal_ = std::move(staging.removal);
        stagingLock_ = staging.descriptor;
        holdAsLive(stagingLock_);
    } catch (...) {
        discard();  // a constructor that throws gets no destructor call
        throw;
    }
}

StagedDirectory::~StagedDirectory() {
    discard();
}

void StagedDirectory::createDirectory(const std::string& what) {
    for (fs::path missing = directory_; !missing.empty() && !fs::exists(fs::symlink_status(missing));
         missing = missing.parent_path()) {
        created_.push_back(missing);
    }
    std::error_code error;
    fs::create_directories(directory_, error);
    if (error) {
        failStaging(directory_, "cannot create " + what, error.message());
    }
}

void StagedDirectory::moveIntoPlace(const std::string& name, const fs::path& destination) const {
    std::error_code error;
    fs::rename(staging_ / name, destination, error);  // replaces a symlink at `destination`, never what it names
    if (error) {
        failStaging(destination, "cannot move the file into place", error.message());
    }
}

void StagedDirectory::removeOthers(const fs::path& directory, const std::function<bool(const std::string&)>& isOwned,
                                   const std::vector<std::string>& kept) {
    std::error_code error;
    for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
         entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        if (isOwned(name) && std::find(kept.begin(), kept.end(), name) == kept.end() &&
            !removeWithoutFollowing(directory, name)) {
            failStaging(entry->path(), "cannot remove an earlier set's file", "it could not be removed");
        }
    }
    if (error) {
        failStaging(directory, "cannot list the directory", error.message());
    }
}

void StagedDirectory::finish() {
    created_.clear();  // the target now holds this set: it stays
    discard();
}

// Removes what an unfinished set made: its files, the staging directory, the directories it created.
void StagedDirectory::discard() {
    if (!staging_.empty()) {
        std::error_code ignored;
        fs::remove_all(staging_, ignored);
        staging_.clear();
    }
    removal_.reset();
    if (stagingLock_ >= 0) {
        ::close(stagingLock_);
        stagingLock_ = -1;
    }
    for (const fs::path& directory : created_) {
        ::rmdir(directory.c_str());  // only if empty: another writer's files stay
    }
    created_.clear();
}

}  // namespace hexray::io
