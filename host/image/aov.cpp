#include "image/aov.h"

#include <algorithm>
#include <cctype>

#include "image/aov_set_writer.h"
#include "io/staged_directory.h"
#include "io/temporary_names.h"

namespace hexray::inline image {
namespace {
namespace fs = std::filesystem;
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
    : staged_(std::make_unique<StagedDirectory>(directory, kAovStagingPrefix, "the AOV directory")),
      writer_(std::make_unique<AovSetWriter>(staged_->staging(), layout, provenance)) {}

StagedAovs::~StagedAovs() = default;

void StagedAovs::writeRows(const AovBand& band) {
    writer_->writeRows(band);
}

std::vector<fs::path> StagedAovs::commit() {
    const std::vector<std::string> names = writer_->finish();
    writer_.reset();
    std::vector<fs::path> committed;
    for (const std::string& name : names) {
        committed.push_back(staged_->directory() / name);
        staged_->moveIntoPlace(name, committed.back());
    }
    staged_->finish();
    // Then an earlier set's files that this one did not replace: its extra lights, its margin.
    StagedDirectory::removeOthers(staged_->directory(), isAovFileName, names);
    return committed;
}

}  // namespace hexray::image
