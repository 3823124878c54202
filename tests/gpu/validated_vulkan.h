#pragma once
// Test fixture: a Vulkan context with the Khronos validation layer on. Any warning or error it
// reports, including during teardown, fails the test.

#include <memory>

#include <gtest/gtest.h>

#include "precision/precision.h"
#include "vulkan/vulkan_context.h"

namespace hexray::test {

class ValidatedVulkanTest : public ::testing::Test {
protected:
    void SetUp() override { context_ = std::make_unique<VulkanContext>(VulkanContext::Options{&validation_, ""}); }

    void TearDown() override {
        context_.reset();
        EXPECT_EQ(validation_.messageCount.load(), 0u) << "the validation layer reported messages (printed above)";
    }

    const VulkanContext& context() const { return *context_; }
    bool onLavapipe() const { return context_->selected().name.find("llvmpipe") != std::string::npos; }

private:
    ValidationLog validation_;
    std::unique_ptr<VulkanContext> context_;
};

// The same, for a test run once per precision: f64 is skipped on a device without shaderFloat64.
class PrecisionVulkanTest : public ValidatedVulkanTest, public ::testing::WithParamInterface<Precision> {
protected:
    void SetUp() override {
        ValidatedVulkanTest::SetUp();
        if (GetParam() == Precision::F64 && !context().selected().hasFloat64) {
            GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
        }
    }
};

}  // namespace hexray::test
