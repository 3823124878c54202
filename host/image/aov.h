#pragma once
// Arbitrary output values beside a render (`hexray render --aov DIR`, `compare --aov DIR`):
// float OpenEXR files and a false-colour PNG preview of each. All from the pixel's first
// sample, like the classification.
//
//   depth.exr       Y: hit distance from the eye in world units; +inf for the background
//   normal.exr      R, G, B: the shading normal's x, y, z (it faces the ray); 0 for the background
//   object-id.exr   Y: node index; -1 for the background
//   light-<i>.exr   Y: 1 where light i reaches the point, 0 where it is shadowed or faces away,
//                   and 0 where lights do not apply (background, constant shaders); lights 0..30
//   margin.exr      Y (compare only): the CPU reference's smallest decision margin, in units of
//                   that decision's error bound at the compared precision (cpu_margins.h); +inf
//                   where no decision was made; below 1 the pixel is ambiguous
//
// Previews: depth on a log scale from near = bright yellow to far = dark blue, background black; normal as
// (n + 1) / 2 in RGB; object id a colour per node, background black; lights white where lit;
// margin log10 from the ambiguity threshold (dark) to 1e9 times it (bright), ambiguous pixels red,
// no decision black.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "image/pixel_class.h"
#include "image/provenance.h"

namespace hexray::inline io {
class StagedDirectory;  // io/staged_directory.h
}  // namespace hexray::io

namespace hexray::inline image {

class AovSetWriter;

// What a set holds.
struct AovLayout {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::size_t lightCount = 0;    // a mask for each of the first PixelClass::kClassifiedLights
    bool withMargins = false;      // margin.exr (compare's CPU reference)
    double ambiguityMargin = 0.0;  // with margins: the threshold the preview marks
};

// The next rows of every AOV, row-major, rows × width values each.
struct AovBand {
    std::uint32_t rows = 0;
    std::span<const float> depth;
    std::span<const glm::vec3> normals;
    std::span<const PixelClass> classes;  // object id and light masks
    std::span<const float> margins;       // with AovLayout::withMargins
};

// Whether `name` is a file an AOV set may hold: depth, normal, object-id, margin or light-N,
// as .exr or .png.
bool isAovFileName(const std::string& name);

// One render's AOVs, written band by band into a hidden staging directory inside `directory`
// (`.hexray-aov-XXXXXX`) and moved into `directory` by commit(), after the image itself is in
// place. commit() also removes the AOV files of an earlier set that this one lacks (light-N
// beyond its lights, margin), so the directory never mixes two renders' AOVs. Destroyed
// without commit() (a failure, an exception), or ended by a catchable signal, it removes the
// staging directory and leaves `directory` as it was, removing it (and any parents) if it
// created it. A staging directory that a killed process left behind is removed by the next set
// staged in the same directory.
class StagedAovs {
public:
    // Creates `directory` if needed; throws OutputError when it or a file cannot be written.
    // Every file records `provenance` (aov_set_writer.h).
    StagedAovs(const std::filesystem::path& directory, const AovLayout& layout, const Provenance& provenance);
    ~StagedAovs();
    StagedAovs(const StagedAovs&) = delete;
    StagedAovs& operator=(const StagedAovs&) = delete;

    void writeRows(const AovBand& band);

    // Finishes every file and moves it into place; returns their paths. Throws OutputError on failure.
    std::vector<std::filesystem::path> commit();

private:
    std::unique_ptr<StagedDirectory> staged_;
    std::unique_ptr<AovSetWriter> writer_;  // after staged_: its files close before the staging directory goes
};

}  // namespace hexray::image
