#pragma once
// Between a strip's stamp (strip_stamp.h) and the provenance record every image carries
// (image/provenance.h): the stamp's renderer is written from the record a piece is rendered
// with, and a merged image records what its pieces' stamps share.

#include <string>

#include "image/provenance.h"
#include "strip/strip_stamp.h"

namespace hexray::inline strip {

// The renderer a stamp names: "gpu f32 on <device>", or "cpu reference" for the CPU backend.
std::string stripRenderer(const Provenance& provenance);

// What the image merged from pieces of `stamp`'s image records: its version, scene, renderer,
// spp and size, the image "merged strips". A field the stamp does not hold in hexray's own form
// (a renderer or version another build wrote otherwise) is left out rather than guessed.
Provenance mergedProvenance(const StripStamp& stamp);

}  // namespace hexray::strip
