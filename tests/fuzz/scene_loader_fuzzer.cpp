// libFuzzer target for the scene loader: any bytes must either load into a scene that keeps
// every invariant the renderers rely on, or be rejected with a SceneError naming the place.
// Anything else (another exception, a crash, a sanitizer report, a violated invariant) traps.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/scene_invariants.h"
#include "scene/scene_loader.h"

namespace {

[[noreturn]] void failWith(const char* what, const std::string& detail) {
    std::fprintf(stderr, "scene_loader_fuzzer: %s: %s\n", what, detail.c_str());
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string source = "fuzz.json";
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const hexray::Scene scene = hexray::parseScene(text, source);
        if (const auto violation = hexray::test::sceneInvariantViolation(scene)) {
            failWith("accepted a scene that breaks an invariant", *violation);
        }
    } catch (const hexray::SceneError& error) {
        if (!hexray::test::rejectionNamesPlace(error.what(), source)) {
            failWith("rejection does not name the place", error.what());
        }
    } catch (const std::exception& error) {
        failWith("exception other than SceneError", error.what());
    } catch (...) {
        failWith("exception other than SceneError", "(not a std::exception)");
    }
    return 0;
}
