// A whole frame with Embree, as a small program of its authors' kind would make it: load a scene
// file, build Embree's scene, trace and shade it (EmbreePacketRenderer: the widest native packets,
// float shading) and write the PNG. The yardstick of `hexray render`'s whole process in
// tools/frame-bench.py, which runs both and compares wall time and peak memory. It loads the file
// with hexray's own loader, so that both programs read the same scenes the same way. Prints each
// phase's milliseconds. A figure for the reader, not a test.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "embree/embree_packet_renderer.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"

using namespace hexray;

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"One frame with Embree: load, build and trace, write a PNG"};
    std::filesystem::path scenePath;
    std::filesystem::path output;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    unsigned threads = 2;
    app.add_option("scene", scenePath, "a hexray scene file")->required()->check(CLI::ExistingFile);
    app.add_option("output", output, "the PNG to write")->required();
    app.add_option("--width", width, "the image's width (default: the scene's)")
        ->check(CLI::Range(1u, kMaxImageDimension));
    app.add_option("--height", height, "the image's height (default: the scene's)")
        ->check(CLI::Range(1u, kMaxImageDimension));
    app.add_option("--threads", threads, "threads tracing and building")->check(CLI::Range(1u, 256u));
    CLI11_PARSE(app, argc, argv);

    try {
        auto start = std::chrono::steady_clock::now();
        Scene scene = loadSceneFile(scenePath);
        if (width != 0 || height != 0) {
            overrideImageSize(scene, width != 0 ? width : scene.image.width, height != 0 ? height : scene.image.height,
                              "--width/--height");
        }
        const double load = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        const EmbreePacketRenderer renderer(threads);
        const EmbreeRender render = renderer.render(scene);
        const double buildAndTrace = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        writePng(output, encodeImage(render.image, scene.image.encoding));
        const double write = millisecondsSince(start);
        std::printf("load %.1f ms, build and trace %.1f ms (trace %.1f), write %.1f ms\n", load, buildAndTrace,
                    render.renderMilliseconds, write);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "hexray_embree_frame: %s\n", error.what());
        return 1;
    }
    return 0;
}
