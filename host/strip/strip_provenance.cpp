#include "strip/strip_provenance.h"

#include <string_view>

namespace hexray::inline strip {
namespace {

constexpr std::string_view kCpuRenderer = "cpu reference";
constexpr std::string_view kGpuPrefix = "gpu ";
constexpr std::string_view kDeviceSeparator = " on ";
constexpr std::string_view kGitPrefix = " (git ";

// The backend, device and precision of a stamp's renderer, the inverse of stripRenderer.
void readRenderer(const std::string& renderer, Provenance& provenance) {
    if (renderer == kCpuRenderer) {
        provenance.backend = "cpu";
        provenance.device = std::string(kCpuRenderer);
        provenance.precision = "f64";
        return;
    }
    const std::size_t on = renderer.find(kDeviceSeparator);
    if (renderer.rfind(kGpuPrefix, 0) == 0 && on != std::string::npos && on > kGpuPrefix.size()) {
        provenance.backend = "gpu";
        provenance.precision = renderer.substr(kGpuPrefix.size(), on - kGpuPrefix.size());
        provenance.device = renderer.substr(on + kDeviceSeparator.size());
    }
}

// A stamp's version, "0.1.0 (git 9317900a2b4c)" as buildVersion() writes it, in its two fields.
void readVersion(const std::string& version, Provenance& provenance) {
    const std::size_t git = version.find(kGitPrefix);
    if (git == std::string::npos || git == 0 || version.back() != ')') {
        return;
    }
    provenance.version = version.substr(0, git);
    provenance.gitRevision = version.substr(git + kGitPrefix.size(), version.size() - 1 - git - kGitPrefix.size());
}

}  // namespace

std::string stripRenderer(const Provenance& provenance) {
    if (provenance.backend == "cpu") {
        return std::string(kCpuRenderer);
    }
    return std::string(kGpuPrefix) + provenance.precision + std::string(kDeviceSeparator) + provenance.device;
}

Provenance mergedProvenance(const StripStamp& stamp) {
    Provenance provenance;
    readVersion(stamp.version, provenance);
    provenance.image = "merged strips";
    provenance.scene = stamp.scene;
    readRenderer(stamp.renderer, provenance);
    provenance.samplesPerPixel = stamp.samplesPerPixel;
    provenance.width = stamp.width;
    provenance.height = stamp.height;
    return provenance;
}

}  // namespace hexray::strip
