#pragma once
// The CPU reference renderer: the same model as the shader, written independently,
// in double precision and for clarity rather than speed, in the eye's frame (eye_frame.h).

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "accel/bvh.h"
#include "camera/camera.h"
#include "cpu/cpu_intersect.h"
#include "cpu/cpu_margins.h"
#include "cpu/eye_frame.h"
#include "image/image.h"
#include "image/pixel_class.h"
#include "scene/scene.h"

namespace hexray::inline cpu {

struct CpuRender {
    Image image;
    std::vector<PixelClass> classes;  // per pixel, row-major like the image
    // Per pixel, the smallest relative margin, in float32 terms (see DecisionRoundoff), of any
    // discrete decision made for it in any sample (hit or miss, which node, which checker cell,
    // facing each light, shadowed or not); infinity when no decision was made. Below
    // kAmbiguityMargin the pixel is ambiguous.
    std::vector<float> margins;
    // Per pixel, which parts of its class are near-tied (from its first sample, whose decisions
    // the class records; a near-tie in another sample marks the colour).
    std::vector<PixelAmbiguity> ambiguity;
    // With AOVs asked for, from each pixel's first sample (as the classes): the hit distance
    // (+inf for the background) and the shading normal (facing the ray; 0 for the background).
    std::vector<float> depth;
    std::vector<glm::vec3> normals;

    bool isAmbiguous(std::size_t pixel) const { return ambiguity[pixel].any(); }
};

// The camera ray of sample `sample` of pixel (x, y).
Ray cameraRay(const PixelSheet& sheet, const ImageSettings& image, std::uint32_t x, std::uint32_t y,
              std::uint32_t sample);

// The most worker threads a render starts, whatever is asked: beyond this, starting them costs
// more than they can gain.
inline constexpr unsigned kMaxCpuThreads = 1024;

// The worker threads renderOnCpu uses for `requested` (0 = all cores, at least 1).
unsigned cpuThreadCount(unsigned requested);

// Renders a scene a band of rows at a time into storage the caller provides and reuses, so that
// what is in memory depends on the image's width, not its area. Every band is exactly those rows
// of renderOnCpu's result.
class CpuBandRenderer {
public:
    // `threadCount`: 0 = all cores; at most kMaxCpuThreads and the image's height are used.
    // `withAovs`: also the depth and normals. `roundoff`: the arithmetic the margins are read
    // against (that of the render to be compared). Throws std::out_of_range for a node whose
    // shader index is out of range.
    CpuBandRenderer(const Scene& scene, unsigned threadCount, Acceleration acceleration = Acceleration::Auto,
                    bool withAovs = false, DecisionRoundoff roundoff = {});

    // The threads each band is shared among (at most the band's rows).
    unsigned threadCount() const { return threads_; }

    // Rows that keep a band's storage near `bandBytes` at this scene's width (at least one).
    std::uint32_t rowsPerBand(std::size_t bandBytes) const;

    // Renders rows [firstRow, firstRow + rows) into `band`, resized to width x rows. With
    // `rowsDone`, the calling thread tells it how many of the band's rows are finished, a few
    // times a second while the workers render and once at the end with `rows`.
    void render(std::uint32_t firstRow, std::uint32_t rows, CpuRender& band,
                const std::function<void(std::uint32_t)>& rowsDone = {}) const;

private:
    EyeFrameScene frame_;
    PixelSheet sheet_;
    std::optional<Bvh> bvh_;
    unsigned threads_;
    bool withAovs_;
    DecisionRoundoff roundoff_;
};

// Renders image.samplesPerPixel rays per pixel, rows spread over `threadCount` threads
// (0 = all cores).
// Scenes with many spheres are traversed through a BVH (see accel/bvh.h, bvhPays).
CpuRender renderOnCpu(const Scene& scene, unsigned threadCount = 0);

// How renderOnCpu finds what a ray meets (Auto: a BVH when bvhPays(scene)). Every choice
// gives the same image, classes and margins bit for bit. `withAovs`: also the depth and normals.
// `roundoff`: as for CpuBandRenderer.
CpuRender renderOnCpu(const Scene& scene, unsigned threadCount, Acceleration acceleration, bool withAovs = false,
                      DecisionRoundoff roundoff = {});

// The margin renderOnCpu would give pixel (x, y) (in float32 terms), without rendering the others.
float pixelMargin(const Scene& scene, std::uint32_t x, std::uint32_t y);

}  // namespace hexray::cpu
