// Between a strip's stamp and the provenance record: the stamp's renderer written from a record,
// and the record of a merged image read back from its pieces' stamp.

#include <gtest/gtest.h>

#include "strip/strip_provenance.h"

namespace hexray {
namespace {

StripStamp stampWith(const std::string& renderer, const std::string& version) {
    return StripStamp{{1, 3}, 640, 480, 4, renderer, "0123456789abcdef/99", version};
}

TEST(StripProvenance, AStampNamesTheRendererOfItsRecord) {
    Provenance gpu;
    gpu.backend = "gpu";
    gpu.precision = "f32";
    gpu.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
    EXPECT_EQ(stripRenderer(gpu), "gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits)");
    Provenance cpu;
    cpu.backend = "cpu";
    cpu.precision = "f64";
    cpu.device = "cpu reference";
    EXPECT_EQ(stripRenderer(cpu), "cpu reference");
}

TEST(StripProvenance, AMergedImageRecordsWhatItsPiecesStampsShare) {
    const Provenance gpu =
        mergedProvenance(stampWith("gpu f64 on llvmpipe (LLVM 15.0.6, 256 bits)", "0.1.0 (git 0123456789ab)"));
    EXPECT_EQ(gpu, (Provenance{"0.1.0", "0123456789ab", "merged strips", "0123456789abcdef/99", "gpu",
                               "llvmpipe (LLVM 15.0.6, 256 bits)", "f64", 4, 640, 480}));
    const Provenance cpu = mergedProvenance(stampWith("cpu reference", "0.1.0 (git 0123456789ab)"));
    EXPECT_EQ(cpu.backend, "cpu");
    EXPECT_EQ(cpu.device, "cpu reference");
    EXPECT_EQ(cpu.precision, "f64");
}

TEST(StripProvenance, WhatAStampDoesNotHoldInHexraysFormIsLeftOut) {
    const Provenance odd = mergedProvenance(stampWith("embree", "custom build"));
    EXPECT_EQ(odd.version, "");
    EXPECT_EQ(odd.gitRevision, "");
    EXPECT_EQ(odd.backend, "");
    EXPECT_EQ(odd.device, "");
    EXPECT_EQ(odd.precision, "");
    EXPECT_EQ(odd.scene, "0123456789abcdef/99");
    EXPECT_EQ(odd.samplesPerPixel, 4u);
}

}  // namespace
}  // namespace hexray
