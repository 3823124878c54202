#pragma once
// compareRenders() band by band: a render under test against the reference, accumulated as the
// bands arrive (in order), so that neither image need be whole in memory. The result is the
// same, bit for bit, as compareRenders on the whole images.

#include <vector>

#include "compare/compare.h"
#include "compare/error_accumulator.h"

namespace hexray::inline compare {

// One render's band of rows: its linear colour, classes and 8-bit encoding.
struct RenderBand {
    const Image& image;
    const std::vector<PixelClass>& classes;
    const Rgb8Image& encoded;
};

class RenderComparator {
public:
    // `ambiguity`: the reference's near-tied decisions in this band (empty: none).
    void add(const RenderBand& reference, const RenderBand& test, const Ambiguities& ambiguity);
    RenderComparison result() const;

private:
    TopologyComparison topology_;
    ErrorAccumulator linear_{1.0 / 255.0, 1.0};
    ErrorAccumulator encoded_{1.0, 255.0};
    std::uint64_t invalidColours_ = 0;
};

}  // namespace hexray::compare
