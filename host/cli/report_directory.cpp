#include "cli/report_directory.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <system_error>

#include "cli/json_document.h"
#include "io/output_error.h"
#include "io/output_file.h"
#include "io/output_plan.h"
#include "io/remove_without_following.h"
#include "io/removed_on_signal.h"
#include "io/stale_temporaries.h"
#include "io/temporary_names.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& what, const std::string& why) {
    throw OutputError(printable(path.string()) + ": " + what + ": " + why);
}

void writeWhole(const fs::path& path, const std::string& text) {
    OutputFile file(path.string());
    if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
        file.fail("cannot write", "short write");
    }
    file.commit();
}

void moveIntoPlace(const fs::path& from, const fs::path& to) {
    std::error_code error;
    fs::rename(from, to, error);  // replaces a symlink at `to`, never what it names
    if (error) {
        fail(to, "cannot move the report's file into place", error.message());
    }
}

// DIR/images, if there, as a directory of this DIR's own: a symlink (which would send the images
// elsewhere) or anything else is refused.
void refuseForeignImageDirectory(const fs::path& images) {
    struct stat status {};
    if (::lstat(images.c_str(), &status) == 0 && !S_ISDIR(status.st_mode)) {
        fail(images, "cannot hold the report's images", "not a directory (a symlink is not followed)");
    }
}

void requireImageDirectory(const fs::path& images) {
    if (::mkdir(images.c_str(), 0777) != 0 && errno != EEXIST) {
        fail(images, "cannot create the report's image directory", std::generic_category().message(errno));
    }
    refuseForeignImageDirectory(images);
}

}  // namespace

void ReportDirectory::addToPlan(OutputPlan& plan, const std::string& directory) {
    plan.addDirectory("--report", directory, isReportFileName);
    plan.addDirectory("--report", fs::path(directory) / kReportImages, isReportImageName);
}

ReportDirectory::ReportDirectory(const std::string& directory) : directory_(directory) {
    try {
        refuseForeignImageDirectory(directory_ / kReportImages);
        createDirectory();
        removeStaleTemporaries(directory_);
        // Inside DIR, so that commit() renames within one file system.
        RegisteredTemporary staging = createTemporary(
            (directory_ / std::string(kReportStagingPrefix)).string() + "XXXXXX", RemovedOnSignal::Kind::Directory);
        if (staging.descriptor < 0) {
            fail(directory_, "cannot create a staging directory", std::generic_category().message(errno));
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

ReportDirectory::~ReportDirectory() {
    discard();
}

void ReportDirectory::createDirectory() {
    for (fs::path missing = directory_; !missing.empty() && !fs::exists(fs::symlink_status(missing));
         missing = missing.parent_path()) {
        created_.push_back(missing);
    }
    std::error_code error;
    fs::create_directories(directory_, error);
    if (error) {
        fail(directory_, "cannot create the report directory", error.message());
    }
}

std::array<fs::path, 4> ReportDirectory::stagedImages(const std::string& stem) const {
    std::array<fs::path, 4> paths;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        paths[i] = staging_ / reportImageName(stem, kReportImageKinds[i]);
    }
    return paths;
}

void ReportDirectory::commit(const std::string& page, const nlohmann::json& results,
                             const std::vector<std::string>& stems) {
    writeJson((staging_ / kReportResults).string(), results);
    writeWhole(staging_ / kReportPage, page);
    std::vector<std::string> images;
    for (const std::string& stem : stems) {
        for (const ReportImage image : kReportImageKinds) {
            images.push_back(reportImageName(stem, image));
        }
    }
    moveImagesIntoPlace(images);
    moveIntoPlace(staging_ / kReportResults, directory_ / kReportResults);
    moveIntoPlace(staging_ / kReportPage, directory_ / kReportPage);
    created_.clear();  // DIR now holds this report: it stays
    discard();
}

// The images, then an earlier report's that this one did not replace.
void ReportDirectory::moveImagesIntoPlace(const std::vector<std::string>& images) const {
    const fs::path directory = directory_ / kReportImages;
    requireImageDirectory(directory);
    for (const std::string& name : images) {
        moveIntoPlace(staging_ / name, directory / name);
    }
    std::error_code error;
    for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
         entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        if (isReportImageName(name) && std::find(images.begin(), images.end(), name) == images.end() &&
            !removeWithoutFollowing(directory, name)) {
            fail(entry->path(), "cannot remove an earlier report's image", "it could not be removed");
        }
    }
    if (error) {
        fail(directory, "cannot list the report's image directory", error.message());
    }
}

// Removes what an uncommitted report made: its files, the staging directory, the directories it created.
void ReportDirectory::discard() {
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

}  // namespace hexray::cli
