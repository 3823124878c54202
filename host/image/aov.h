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
//   margin.exr      Y (compare only): the CPU reference's smallest decision margin; +inf where
//                   no decision was made; below 2^-17 the pixel is ambiguous
//
// Previews: depth on a log scale from near = bright yellow to far = dark blue, background black; normal as
// (n + 1) / 2 in RGB; object id a colour per node, background black; lights white where lit;
// margin log10 from 1e-12 (dark) to 1 (bright), ambiguous pixels red, no decision black.

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

#include "image/pixel_class.h"

namespace hexray {

struct AovSet {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> depth;
    std::vector<glm::vec3> normals;
    std::vector<PixelClass> classes;      // object id and light masks
    std::size_t lightCount = 0;
    const std::vector<float>* margins = nullptr;  // written when given
    double ambiguityMargin = 0.0;                 // with margins: the threshold the preview marks
};

// One render's AOVs, written whole into a hidden staging directory inside `directory` by the
// constructor and moved into `directory` by commit(), after the image itself is in place.
// commit() also removes the AOV files of an earlier set that this one lacks (light-N beyond
// its lights, margin), so the directory never mixes two renders' AOVs. Destroyed without
// commit() (a failure, an exception), it removes the staging directory and leaves
// `directory` as it was. A process killed outright may leave a `.hexray-aov-*` directory.
class StagedAovs {
public:
    // Creates `directory` if needed; throws ImageIoError when a file cannot be written.
    StagedAovs(const std::filesystem::path& directory, const AovSet& aovs);
    ~StagedAovs();
    StagedAovs(const StagedAovs&) = delete;
    StagedAovs& operator=(const StagedAovs&) = delete;

    // Moves every file into place; returns their paths. Throws ImageIoError on failure.
    std::vector<std::filesystem::path> commit();

private:
    std::filesystem::path directory_;
    std::filesystem::path staging_;  // empty once committed
    std::vector<std::string> names_;  // file names, in the order written
};

}  // namespace hexray
