// The README and docs/ are self-contained: every relative link names a file in the repository.

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> documents() {
    std::vector<fs::path> files = {test::sourcePath("README.md")};
    for (const auto& entry : fs::directory_iterator(test::sourcePath("docs"))) {
        if (entry.path().extension() == ".md")
            files.push_back(entry.path());
    }
    return files;
}

TEST(Docs, EveryRelativeLinkNamesAFileInTheRepository) {
    const fs::path root = fs::canonical(test::sourcePath(""));
    const std::regex link(R"(\]\(([^)#\s]+)[^)]*\))");
    for (const fs::path& document : documents()) {
        std::ifstream in(document);
        std::stringstream text;
        text << in.rdbuf();
        const std::string content = text.str();
        for (auto match = std::sregex_iterator(content.begin(), content.end(), link); match != std::sregex_iterator();
             ++match) {
            const std::string target = (*match)[1];
            if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0)
                continue;
            const fs::path resolved = fs::weakly_canonical(document.parent_path() / target);
            EXPECT_TRUE(fs::exists(resolved)) << document.filename() << ": " << target;
            EXPECT_EQ(resolved.string().rfind(root.string(), 0), 0u)
                << document.filename() << ": " << target << " is outside the repository";
        }
        EXPECT_EQ(content.find("../shared"), std::string::npos) << document.filename();
    }
}

}  // namespace
}  // namespace hexray
