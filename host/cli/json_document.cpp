#include "cli/json_document.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "io/output_error.h"
#include "io/output_file.h"
#include "util/build_version.h"
#include "util/milliseconds_since.h"

namespace hexray::cli {
namespace {

const std::chrono::steady_clock::time_point processStart = std::chrono::steady_clock::now();

}  // namespace

nlohmann::json jsonDocument(const std::string& command) {
    return {{"schema", "hexray-" + command + "/" + std::to_string(kJsonSchemaVersion)},
            {"command", command},
            {"hexray", {{"version", hexrayVersion()}, {"git", hexrayGitRevision()}}}};
}

nlohmann::json jsonDevice(const DeviceInfo& device) {
    return {{"name", device.name},
            {"driver", device.driver},
            {"type", deviceTypeName(device.type)},
            {"api", device.apiVersion}};
}

nlohmann::json jsonNumber(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json jsonNumber(const std::optional<double>& value) {
    return value ? jsonNumber(*value) : nlohmann::json(nullptr);
}

const char* exitCodeName(int code) {
    switch (code) {
        case kSuccess:
            return "success";
        case kToleranceExceeded:
            return "tolerance_exceeded";
        case kBadInput:
            return "bad_input";
        case kVulkanUnavailable:
            return "vulkan_unavailable";
        case kValidationFailed:
            return "validation_failed";
        case kOutputFailed:
            return "output_failed";
        case kDeviceLost:
            return "device_lost";
        case kOutOfDeviceMemory:
            return "out_of_device_memory";
        case kSizeMismatch:
            return "size_mismatch";
        default:
            return "internal_error";
    }
}

double processMilliseconds() {
    return millisecondsSince(processStart);
}

void recordExit(nlohmann::json& document, int code) {
    document["exit"] = {{"code", code}, {"name", exitCodeName(code)}, {"messages", errorsPrinted()}};
    document["timings_ms"]["wall"] = processMilliseconds();
}

void writeJson(const std::string& path, const nlohmann::json& document) {
    const std::string text = document.dump(2) + "\n";
    OutputFile file(path);
    if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
        file.fail("cannot write", "short write");
    }
    file.commit();
}

int finishJson(const std::string& path, nlohmann::json& document, int code) {
    if (path.empty()) {
        return code;
    }
    recordExit(document, code);
    const int written = guarded([&] {
        try {
            writeJson(path, document);
        } catch (const OutputError& error) {
            // The command checks its outputs before any work: a path it already reported is not
            // reported again.
            const std::vector<std::string>& printed = errorsPrinted();
            if (std::find(printed.begin(), printed.end(), std::string(error.what())) != printed.end()) {
                return int(kOutputFailed);
            }
            throw;
        }
        return int(kSuccess);
    });
    return written == kSuccess ? code : written;
}

}  // namespace hexray::cli
