#pragma once
// Which work the rays of each screen tile can possibly need, decided on the host in double
// before the render: the nodes a camera ray of the tile may hit, and for each light the spheres
// that may lie between a point the tile sees and the light. Tiles that need the same work form a
// class, and each class gets a kernel generated for just that work (lavapipe runs both sides of
// every branch, so only a kernel without the code saves its cost). Conservative: a test is left
// out only when no ray of the tile can pass it, with a margin far beyond the shader's rounding,
// so the image is bit-identical to the unculled render.

#include <cstdint>
#include <vector>

#include "gpu/render_plan.h"
#include "scene/scene.h"

namespace hexray::inline gpu {

// A tile's work: bit i of `primary` when a camera ray of the tile may hit node i; per light, bit i
// of `shadow` when sphere node i may shadow a point the tile sees (planes are never culled: their
// test is a sign comparison).
struct TileWork {
    std::uint32_t primary = 0;
    std::vector<std::uint32_t> shadow;
    auto operator<=>(const TileWork&) const = default;
};

// Tiles of WORKGROUP_SIZE x WORKGROUP_SIZE pixels, row-major from the top left.
struct TileClassification {
    std::uint32_t tilesX = 0;
    std::uint32_t tilesY = 0;
    std::vector<TileWork> classes;           // at most the maximum asked for
    std::vector<std::uint32_t> classOfTile;  // tilesX * tilesY entries
};

// The classification for a generated kernel's scene (`code` is its unculled work), with at most
// `maxClasses` classes: past that, the classes of fewest tiles are merged into the ones whose work
// grows least.
TileClassification classifyTiles(const Scene& scene, const SceneCode& code, std::size_t maxClasses);

// `code` restricted to a class's work: the nodes its camera rays test and the shadow tests it runs.
SceneCode codeForClass(const SceneCode& code, const TileWork& work);

// Tests a kernel runs per pixel, on average over the image: camera-ray node tests, lights whose
// shadow ray is traced (at least one shadow test), and shadow node tests. Straight-line kernels run
// every test they contain for every pixel.
struct WorkPerPixel {
    double primaryTests = 0;
    double shadowRays = 0;
    double shadowTests = 0;
    bool operator==(const WorkPerPixel&) const = default;
};
WorkPerPixel workPerPixel(const SceneCode& code);  // the unculled kernel
WorkPerPixel workPerPixel(const SceneCode& code, const TileClassification& classification, const ImageSettings& image);

}  // namespace hexray::gpu
