// libFuzzer target for the reader of `hexray merge`'s pieces (strip/strip_piece.h): any bytes, given
// as a piece through an in-memory file (a memfd, read as merge reads a piece's descriptor), must
// be a verified piece or a refusal naming it (piece_judgement.h); in PNG when they start with
// PNG's signature, else in OpenEXR. A crash, a leak, a sanitizer report, a broken judgement or,
// with ci/fuzz.sh's -malloc_limit_mb, an allocation sized from an unchecked field, traps.

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "fuzz/piece_judgement.h"

namespace {

constexpr char kName[] = "fuzz-piece";

[[noreturn]] void failWith(const char* what, const std::string& detail) {
    std::fprintf(stderr, "strip_piece_fuzzer: %s: %s\n", what, detail.c_str());
    __builtin_trap();
}

// The in-memory file, made once and refilled for each input.
int memoryFile() {
    static const int descriptor = ::memfd_create(kName, MFD_CLOEXEC);
    if (descriptor < 0)
        failWith("memfd_create", std::strerror(errno));
    return descriptor;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const int descriptor = memoryFile();
    if (::ftruncate(descriptor, 0) != 0 || (size && ::pwrite(descriptor, data, size, 0) != ssize_t(size))) {
        failWith("cannot fill the in-memory file", std::strerror(errno));
    }
    const int own = ::dup(descriptor);  // the piece closes its descriptor
    if (own < 0)
        failWith("dup", std::strerror(errno));
    const bool png = size >= 8 && std::memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0;
    const hexray::test::PieceVerdict verdict = hexray::test::judgePiece(
        hexray::ReadOnlyFile(own, kName), png ? hexray::ImageFormat::Png : hexray::ImageFormat::Exr);
    if (verdict.violation) {
        failWith("broke the piece reader's contract", *verdict.violation);
    }
    return 0;
}
