#include "cli/report_layout.h"

#include <cstdio>
#include <string_view>

namespace hexray::cli {
namespace {

// Long enough to recognise the scene, short enough for any file system's name limit.
constexpr std::size_t kMaxNameBytes = 80;

constexpr std::array<std::string_view, 4> kSuffixes = {"-gpu.png", "-cpu.png", "-diff.png", "-mask.png"};

bool isSafe(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-';
}

}  // namespace

std::string reportImageStem(std::size_t number, const std::string& sceneName, Precision precision) {
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%03zu-", number);
    std::string name;
    for (const char c : sceneName.substr(0, kMaxNameBytes)) {
        name += isSafe(c) ? c : c == '/' ? '-' : '_';
    }
    return prefix + name + "-" + std::string(precisionName(precision));
}

std::string reportImageName(const std::string& stem, ReportImage image) {
    return stem + std::string(kSuffixes[static_cast<std::size_t>(image)]);
}

bool isReportImageName(const std::string& name) {
    std::size_t digits = 0;
    while (digits < name.size() && name[digits] >= '0' && name[digits] <= '9') {
        ++digits;
    }
    if (digits == 0 || digits == name.size() || name[digits] != '-') {
        return false;
    }
    for (const char c : name) {
        if (!isSafe(c)) {
            return false;
        }
    }
    for (const std::string_view suffix : kSuffixes) {
        if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
            return true;
        }
    }
    return false;
}

bool isReportFileName(const std::string& name) {
    return name == kReportPage || name == kReportResults || name == kReportImages;
}

}  // namespace hexray::cli
