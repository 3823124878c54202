// The README and docs/ are self-contained: every relative link names a file in the repository, and
// every link to a section (`file.md#section`, `#section`) names a heading that file has.

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
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

std::string contentOf(const fs::path& document) {
    std::ifstream in(document);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// GitHub's anchor for a heading: lower case, letters, digits, '-' and '_' kept, spaces as '-', the
// rest dropped. Bytes beyond ASCII are dropped too (no heading here has a non-ASCII letter).
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (const char c : heading) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x80)
            continue;
        if (std::isalnum(byte) || c == '-' || c == '_')
            anchor += static_cast<char>(std::tolower(byte));
        else if (c == ' ')
            anchor += '-';
    }
    return anchor;
}

// The anchors of a Markdown file's headings, outside code blocks.
std::set<std::string> anchorsOf(const std::string& content) {
    std::set<std::string> anchors;
    std::istringstream lines(content);
    bool inCode = false;
    const std::regex heading(R"(^#+\s+(.*?)\s*$)");
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("```", 0) == 0)
            inCode = !inCode;
        std::smatch match;
        if (!inCode && std::regex_match(line, match, heading))
            anchors.insert(anchorOf(match[1]));
    }
    return anchors;
}

TEST(Docs, EveryRelativeLinkNamesAFileInTheRepository) {
    const fs::path root = fs::canonical(test::sourcePath(""));
    const std::regex link(R"(\]\(([^)#\s]+)[^)]*\))");
    for (const fs::path& document : documents()) {
        const std::string content = contentOf(document);
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

TEST(Docs, EveryLinkToASectionNamesAHeadingOfItsFile) {
    std::map<fs::path, std::set<std::string>> anchors;
    for (const fs::path& document : documents())
        anchors[fs::weakly_canonical(document)] = anchorsOf(contentOf(document));
    const std::regex link(R"(\]\(([^)#\s]*)#([^)\s]+)\))");
    int checked = 0;
    for (const fs::path& document : documents()) {
        const std::string content = contentOf(document);
        for (auto match = std::sregex_iterator(content.begin(), content.end(), link); match != std::sregex_iterator();
             ++match) {
            const std::string file = (*match)[1];
            const fs::path target = fs::weakly_canonical(file.empty() ? document : document.parent_path() / file);
            const auto headings = anchors.find(target);
            if (headings == anchors.end())
                continue;  // not a Markdown file of README.md and docs/
            ++checked;
            EXPECT_EQ(headings->second.count((*match)[2]), 1u)
                << document.filename() << ": " << match->str() << " names no heading of " << target.filename();
        }
    }
    EXPECT_GT(checked, 0);
}

TEST(Docs, AnchorsAreGitHubs) {
    EXPECT_EQ(anchorOf("Vulkan faults: messages and exit codes"), "vulkan-faults-messages-and-exit-codes");
    EXPECT_EQ(anchorOf("`--report DIR`: a page to look at"), "--report-dir-a-page-to-look-at");
    EXPECT_EQ(anchorOf("Demo scene, 1920×1080"), "demo-scene-19201080");
}

}  // namespace
}  // namespace hexray
