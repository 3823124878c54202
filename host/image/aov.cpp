#include "image/aov.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <system_error>

#include "image/aov_set_writer.h"
#include "io/output_error.h"
#include "io/removed_on_signal.h"
#include "io/stale_temporaries.h"
#include "io/temporary_names.h"
#include "util/printable.h"

namespace hexray::inline image {
namespace {

namespace fs = std::filesystem;

void removeQuietly(const fs::path& directory) {
    std::error_code ignored;
    fs::remove_all(directory, ignored);
}

[[noreturn]] void fail(const fs::path& path, const std::string& what, const std::string& why) {
    throw OutputError(printable(path.string()) + ": " + what + ": " + why);
}

}  // namespace

bool isAovFileName(const std::string& name) {
    const fs::path path(name);
    const std::string extension = path.extension().string();
    const std::string stem = path.stem().string();
    if (extension != ".exr" && extension != ".png") {
        return false;
    }
    if (stem == "depth" || stem == "normal" || stem == "object-id" || stem == "margin") {
        return true;
    }
    const std::string light = "light-";
    return stem.size() > light.size() && stem.compare(0, light.size(), light) == 0 &&
           std::all_of(stem.begin() + light.size(), stem.end(), [](unsigned char c) { return std::isdigit(c); });
}

StagedAovs::StagedAovs(const fs::path& directory, const AovLayout& layout, const Provenance& provenance)
    : directory_(directory) {
    try {
        createDirectory();
        removeStaleTemporaries(directory_);
        // Inside the target directory, so that commit() renames within one file system.
        RegisteredTemporary staging = createTemporary((directory_ / std::string(kAovStagingPrefix)).string() + "XXXXXX",
                                                      RemovedOnSignal::Kind::Directory);
        if (staging.descriptor < 0) {
            fail(directory_, "cannot create a staging directory", std::generic_category().message(errno));
        }
        staging_ = staging.path;
        removal_ = std::move(staging.removal);
        stagingLock_ = staging.descriptor;
        holdAsLive(stagingLock_);
        writer_ = std::make_unique<AovSetWriter>(staging_, layout, provenance);
    } catch (...) {
        discard();  // a constructor that throws gets no destructor call
        throw;
    }
}

StagedAovs::~StagedAovs() {
    discard();
}

void StagedAovs::createDirectory() {
    for (fs::path missing = directory_; !missing.empty() && !fs::exists(fs::symlink_status(missing));
         missing = missing.parent_path()) {
        created_.push_back(missing);
    }
    std::error_code error;
    fs::create_directories(directory_, error);
    if (error) {
        fail(directory_, "cannot create the AOV directory", error.message());
    }
}

// Removes what an uncommitted set made: its files, the staging directory, the directories it created.
void StagedAovs::discard() {
    writer_.reset();
    if (!staging_.empty()) {
        removeQuietly(staging_);
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

void StagedAovs::writeRows(const AovBand& band) {
    writer_->writeRows(band);
}

std::vector<fs::path> StagedAovs::commit() {
    const std::vector<std::string> names = writer_->finish();
    writer_.reset();
    std::error_code error;
    std::vector<fs::path> committed;
    for (const std::string& name : names) {
        fs::rename(staging_ / name, directory_ / name, error);
        if (error) {
            fail(directory_ / name, "cannot move the AOV into place", error.message());
        }
        committed.push_back(directory_ / name);
    }
    created_.clear();  // the directory now holds this set: it stays
    discard();
    // Then an earlier set's files that this one did not replace: its extra lights, its margin.
    for (const auto& entry : fs::directory_iterator(directory_, error)) {
        const std::string name = entry.path().filename().string();
        if (isAovFileName(name) && std::find(names.begin(), names.end(), name) == names.end()) {
            fs::remove(entry.path(), error);
            if (error) {
                fail(entry.path(), "cannot remove an earlier AOV", error.message());
            }
        }
    }
    if (error) {
        fail(directory_, "cannot list the AOV directory", error.message());
    }
    return committed;
}

}  // namespace hexray::image
