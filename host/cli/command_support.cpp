#include "cli/command_support.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include "cli/progress.h"
#include "gpu/plan_refused.h"
#include "image/image_io.h"
#include "io/output_error.h"
#include "io/output_plan.h"
#include "scene/scene_loader.h"
#include "scene/scene_settings.h"
#include "strip/strip_stamp.h"
#include "util/out_of_memory.h"
#include "util/parallel_parts.h"
#include "util/printable.h"

namespace hexray::cli {

namespace {

std::vector<std::string>& printedErrors() {
    static std::vector<std::string> errors;
    return errors;
}

}  // namespace

void printError(const std::string& message) {
    // Where the text a message quotes is escaped already, this changes nothing; it catches any
    // that is not (a library's message quoting a path).
    printedErrors().push_back(printable(message));
    std::fprintf(stderr, "hexray: error: %s\n", printedErrors().back().c_str());
}

const std::vector<std::string>& errorsPrinted() {
    return printedErrors();
}

int exitCodeFor(VulkanFailure failure) {
    switch (failure) {
        case VulkanFailure::DeviceLost:
            return kDeviceLost;
        case VulkanFailure::OutOfMemory:
            return kOutOfDeviceMemory;
        default:
            return kVulkanUnavailable;
    }
}

int guarded(const std::function<int()>& command) {
    try {
        return command();
    } catch (const SceneError& error) {
        printError(error.what());
        return kBadInput;
    } catch (const VulkanError& error) {
        printError(error.what());
        return exitCodeFor(error.failure());
    } catch (const PlanRefused& error) {
        printError(error.what());
        return kVulkanUnavailable;  // for this scene
    } catch (const vk::SystemError& error) {
        const VulkanError classified = classify(error, "rendering");
        printError(classified.what());
        return exitCodeFor(classified.failure());
    } catch (const StripError& error) {
        printError(error.what());
        return kBadInput;
    } catch (const OutputConflict& error) {
        printError(error.what());
        return kBadInput;
    } catch (const OutputError& error) {
        printError(error.what());
        return kOutputFailed;
    } catch (const ImageIoError& error) {
        printError(error.what());
        return kOutputFailed;
    } catch (const std::filesystem::filesystem_error& error) {
        printError(error.what());
        return kBadInput;  // a path on the command line that cannot be read
    } catch (const OutOfMemory& error) {
        printError(std::string("out of memory: ") + error.what());
        return kInternalError;
    } catch (const std::bad_alloc&) {
        // Everything that grows with the scene says so (OutOfMemory); what is left is the image.
        printError(
            "out of memory: make the image narrower (--width): hexray's memory grows with the image's width "
            "(and, with --aov, its number of lights), not with its height");
        return kInternalError;
    } catch (const std::exception& error) {
        printError(std::string("unexpected failure: ") + error.what());
        return kInternalError;
    }
}

namespace {

Scene readAndParse(const std::string& path, const ImageOverride& image, std::string* identity) {
    const std::string source = sceneSourceName(path);
    std::string text = readSceneFile(path);
    if (!image.settings.empty()) {
        text = withSettings(text, source, image.settings);  // the scene rendered, for its identity too
    }
    Progress progress("loading " + source, text.size(), Progress::Unit::Bytes);
    ParseProgress parseProgress;  // none unless shown: the parser's fastest path
    if (Progress::shown()) {
        parseProgress = [&](std::size_t parsed, std::size_t) { progress.update(parsed); };
    }
    // The identity hashes every byte: for a large file, on a thread of its own beside the parser.
    constexpr std::size_t kHashBesideFrom = std::size_t{1} << 20;
    const bool beside = identity && text.size() >= kHashBesideFrom;
    if (identity && !beside) {
        *identity = sceneTextIdentity(text);
    }
    Scene scene;
    runParts(beside ? 2 : 1, [&](unsigned part) {
        if (part == 1) {
            *identity = sceneTextIdentity(text);
        } else {
            scene = parseScene(text, source, parseProgress);
        }
    });
    applyImageOverride(scene, image);
    return scene;
}

}  // namespace

Scene loadScene(const std::string& path, const ImageOverride& image, std::string* identity) {
    const auto what = [&] {
        std::error_code unknown;
        const std::uintmax_t bytes = std::filesystem::file_size(path, unknown);
        const std::uint64_t mebibytes = (bytes + (std::uint64_t{1} << 20) - 1) >> 20;
        const std::string size = unknown ? "" : " (" + std::to_string(mebibytes) + " MiB)";
        return "the scene file " + printable(path) + size + ": loading a scene takes about twice its file's size";
    };
    return holding(what, [&] { return readAndParse(path, image, identity); });
}

void applyImageOverride(Scene& scene, const ImageOverride& image) {
    if (image.width || image.height) {
        const char* source = !image.height ? "--width" : !image.width ? "--height" : "--width/--height";
        overrideImageSize(scene, image.width.value_or(scene.image.width), image.height.value_or(scene.image.height),
                          source);
    }
    if (image.samplesPerPixel) {
        overrideSamplesPerPixel(scene, *image.samplesPerPixel, "--spp");
    }
}

int withValidationVerdict(int commandCode, const ValidationLog& log) {
    const std::uint32_t count = log.messageCount.load();
    if (commandCode != kSuccess || count == 0) {
        return commandCode;
    }
    printError("the Vulkan validation layer reported " + std::to_string(count) + " message(s)");
    return kValidationFailed;
}

}  // namespace hexray::cli
