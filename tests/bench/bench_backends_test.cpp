// The bench's backends: a round of every configuration, measured again, makes no kernel again, so
// "frame ms" is a frame's cost and not a rebuild's.

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "bench/bench_backends.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

// As `hexray bench` measures the demo: every GPU configuration at 1 and 4 samples a pixel.
std::vector<BenchConfiguration> demoConfigurations(bool float64) {
    std::vector<BenchConfiguration> configurations{{0, BenchBackend::GpuHandWritten, Precision::F32, Culling::Off, 1}};
    for (const std::uint32_t samples : {1u, 4u}) {
        for (const Precision precision : {Precision::F32Naive, Precision::F32, Precision::F64}) {
            for (const Culling culling : {Culling::Off, Culling::On}) {
                if ((precision != Precision::F64 || float64) &&
                    (precision != Precision::F32Naive || culling == Culling::Off)) {
                    configurations.push_back({0, BenchBackend::Gpu, precision, culling, samples});
                }
            }
        }
    }
    return configurations;
}

TEST(BenchBackends, ASecondRoundOfEveryGpuConfigurationMakesNoPipelineAgain) {
    ValidationLog validation;
    auto backends = std::make_unique<BenchBackends>(VulkanContext::Options{&validation, ""});
    const Scene demo = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    const std::vector<BenchConfiguration> configurations = demoConfigurations(backends->hasFloat64());
    const auto round = [&](bool withClasses) {
        for (const BenchConfiguration& configuration : configurations) {
            Scene scene = demo;
            scene.image.samplesPerPixel = configuration.samplesPerPixel;
            BenchMeasurement measurement;
            backends->measure(scene, configuration, withClasses, measurement);
        }
    };
    round(true);  // the bench's first round also renders each configuration's pixel classes
    round(false);
    const std::uint64_t afterTwoRounds = backends->gpuPipelinesCreated();
    EXPECT_GT(afterTwoRounds, configurations.size());  // culling: a kernel per tile class
    round(false);
    EXPECT_EQ(backends->gpuPipelinesCreated(), afterTwoRounds);
    backends.reset();
    EXPECT_EQ(validation.messageCount.load(), 0u) << "the validation layer reported messages (printed above)";
}

}  // namespace
}  // namespace hexray
