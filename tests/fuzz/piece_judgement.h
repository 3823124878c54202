#pragma once
// What `hexray merge` must make of any file given as a piece, judged as the piece fuzzer
// (strip_piece_fuzzer.cpp) and the tests judge it: either a piece whose every row is read and
// whose digest is verified, or a refusal (StripError) that names the piece. Anything else (another
// exception, a stamp beyond the renderer's limits accepted) is a violation. Rows are read in
// bands of at most 64, into buffers sized from the checked stamp only.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/pixel_digest.h"
#include "strip/strip_piece.h"

namespace hexray::test {

struct PieceVerdict {
    bool verified = false;
    std::string pixels;                    // the SHA-256 of the rows read, when verified
    std::string refusal;                   // the StripError's message, when refused
    std::optional<std::string> violation;  // what broke the reader's contract
};

// Returns the SHA-256 of the rows.
inline std::string readEveryRow(StripPiece& piece) {
    PixelDigest digest("");
    constexpr std::uint32_t kBand = 64;
    const std::size_t width = piece.stamp().width;
    std::vector<std::uint8_t> rgb;
    std::vector<float> red, green, blue;
    for (std::uint32_t done = 0; done < piece.rowCount(); done += kBand) {
        const std::uint32_t rows = std::min(kBand, piece.rowCount() - done);
        if (piece.format() == ImageFormat::Png) {
            rgb.resize(rows * width * 3);
            piece.readRgb8Rows(rgb);
            digest.addRgb8Rows(rgb);
        } else {
            for (std::vector<float>* plane : {&red, &green, &blue})
                plane->resize(rows * width);
            piece.readFloatRows(rows, red, green, blue);
            digest.addFloatRows(red, green, blue);
        }
    }
    return digest.hex();
}

inline PieceVerdict judgePiece(ReadOnlyFile file, ImageFormat format) {
    const std::string name = file.name();
    PieceVerdict verdict;
    try {
        StripPiece piece(std::move(file), format);
        if (const std::optional<std::string> problem = beyondRendererLimits(piece.stamp())) {
            verdict.violation = "accepted a stamp beyond the renderer's limits: " + *problem;
            return verdict;
        }
        const std::string pixels = readEveryRow(piece);
        piece.verify();
        verdict.verified = true;
        verdict.pixels = pixels;
    } catch (const StripError& error) {
        verdict.refusal = error.what();
        if (verdict.refusal.rfind(name + ": ", 0) != 0) {
            verdict.violation = "a refusal that does not name the piece: " + verdict.refusal;
        }
    } catch (const std::exception& error) {
        verdict.violation = std::string("an exception other than StripError: ") + error.what();
    }
    return verdict;
}

}  // namespace hexray::test
