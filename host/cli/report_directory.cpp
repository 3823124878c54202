#include "cli/report_directory.h"

#include <sys/stat.h>
#include <cerrno>
#include <cstdio>
#include <system_error>

#include "cli/json_document.h"
#include "io/output_error.h"
#include "io/output_file.h"
#include "io/output_plan.h"
#include "io/staged_directory.h"
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

ReportDirectory::ReportDirectory(const std::string& directory) {
    refuseForeignImageDirectory(fs::path(directory) / kReportImages);
    staged_ = std::make_unique<StagedDirectory>(directory, kReportStagingPrefix, "the report directory");
}

ReportDirectory::~ReportDirectory() = default;

std::array<fs::path, 4> ReportDirectory::stagedImages(const std::string& stem) const {
    std::array<fs::path, 4> paths;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        paths[i] = staged_->staging() / reportImageName(stem, kReportImageKinds[i]);
    }
    return paths;
}

// The images first, then the results and the page that name them; last, an earlier report's
// images that this one did not replace.
void ReportDirectory::commit(const std::string& page, const nlohmann::json& results,
                             const std::vector<std::string>& stems) {
    writeJson((staged_->staging() / kReportResults).string(), results);
    writeWhole(staged_->staging() / kReportPage, page);
    std::vector<std::string> images;
    for (const std::string& stem : stems) {
        for (const ReportImage image : kReportImageKinds) {
            images.push_back(reportImageName(stem, image));
        }
    }
    const fs::path imageDirectory = staged_->directory() / kReportImages;
    requireImageDirectory(imageDirectory);
    for (const std::string& name : images) {
        staged_->moveIntoPlace(name, imageDirectory / name);
    }
    staged_->moveIntoPlace(kReportResults, staged_->directory() / kReportResults);
    staged_->moveIntoPlace(kReportPage, staged_->directory() / kReportPage);
    staged_->finish();
    StagedDirectory::removeOthers(imageDirectory, isReportImageName, images);
}

}  // namespace hexray::cli
