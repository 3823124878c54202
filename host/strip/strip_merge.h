#pragma once
// `hexray merge`: the pieces of a render in strips assembled into the whole image, a band of rows at
// a time, pixel for pixel what a single render writes. In two steps: openPieces opens every piece
// once and checks what the pieces declare; mergePieces reads their rows from those same open
// files into the output and verifies each piece's digest (strip_piece.h).

#include <string>
#include <vector>

#include "image/image_format.h"
#include "strip/strip_piece.h"
#include "strip/strip_stamp.h"

namespace hexray::inline strip {

// Opens every piece in `paths` (raising the soft limit on open files to the hard one if they need
// it) and checks that they are the N strips of one image (the same stamp but for the index), each
// exactly once, each in `format` and of its stamp's size, within the renderer's limits. Returns
// them in strip order. Throws StripError naming the piece that does not fit or the strip missing.
std::vector<StripPiece> openPieces(const std::vector<std::string>& paths, ImageFormat format);

// Writes the image of `strips` (openPieces') to `output` (atomically, see io/output_file.h), in
// the strips' format, recording what their stamps share (mergedProvenance, strip_provenance.h).
// Throws StripError naming a piece whose pixels are not what it recorded, and then no output is
// left.
void mergePieces(const std::string& output, std::vector<StripPiece>& strips);

// Both, in the format `output`'s name asks for. Returns the stamp of the first strip.
StripStamp mergeStrips(const std::string& output, const std::vector<std::string>& paths);

}  // namespace hexray::strip
