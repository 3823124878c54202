#pragma once
// `hexray compare --report DIR`, on disk: every file is written into a hidden staging directory
// inside DIR (`.hexray-report-XXXXXX`, io/staged_directory.h) and moved into place by commit(),
// images first and the page last, so that DIR holds either the earlier report or the whole new
// one, never a page naming images that are not there; commit() also removes an earlier report's
// images that this one does not have. Destroyed without commit(), it leaves DIR as it was. The
// layout: report_layout.h.

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/report_layout.h"

namespace hexray::inline io {
class OutputPlan;
class StagedDirectory;
}  // namespace hexray::io

namespace hexray::cli {

class ReportDirectory {
public:
    // Adds DIR and DIR/images to `plan` as outputs ("--report"), with the names a report owns there.
    static void addToPlan(OutputPlan& plan, const std::string& directory);

    // Creates DIR if needed and the staging directory in it; throws OutputError when it cannot.
    explicit ReportDirectory(const std::string& directory);
    ~ReportDirectory();
    ReportDirectory(const ReportDirectory&) = delete;
    ReportDirectory& operator=(const ReportDirectory&) = delete;

    // Where to write a comparison's images (report_layout.h: the stem, the kinds' order) until commit().
    std::array<std::filesystem::path, 4> stagedImages(const std::string& stem) const;

    // Writes the page and the results beside the staged images (those of `stems`) and moves all
    // into DIR. Throws OutputError on failure.
    void commit(const std::string& page, const nlohmann::json& results, const std::vector<std::string>& stems);

private:
    std::unique_ptr<StagedDirectory> staged_;
};

}  // namespace hexray::cli
