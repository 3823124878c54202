#pragma once
// The plan's answer when a device cannot render a scene as asked. Nothing failed in Vulkan (no
// call was made): the plan knows beforehand that the result would be wrong or impossible. The
// command line treats it as the GPU being unavailable for this scene (exit 3; with --backend auto
// the CPU reference renders it instead).

#include <stdexcept>
#include <string>

namespace hexray::inline gpu {

enum class Refusal {
    NoFloat64,     // --precision f64 on a device without shaderFloat64
    PastLoopLimit  // a pixel needs more loop passes than the device runs (loop_budget.h)
};

class PlanRefused : public std::runtime_error {
public:
    // `advice` (what the user can do) is appended to what(), but not to reason().
    PlanRefused(Refusal refusal, const std::string& reason, const std::string& advice)
        : std::runtime_error(reason + ": " + advice), refusal_(refusal), reason_(reason) {}

    Refusal refusal() const { return refusal_; }
    const std::string& reason() const { return reason_; }

private:
    Refusal refusal_;
    std::string reason_;
};

}  // namespace hexray::gpu
