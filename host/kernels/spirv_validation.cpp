#include "kernels/spirv_validation.h"

#include <spirv-tools/libspirv.hpp>

namespace hexray::inline kernels {

std::optional<std::string> spirvValidationProblem(std::span<const std::uint32_t> spirv) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string firstMessage;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        if (firstMessage.empty() && message) {
            firstMessage = message;
        }
    });
    spvtools::ValidatorOptions options;  // the universal limits at their defaults
    options.SetFriendlyNames(false);     // naming every id for messages costs more than the checks
    if (tools.Validate(spirv.data(), spirv.size(), options)) {
        return std::nullopt;
    }
    return firstMessage.empty() ? "invalid SPIR-V" : firstMessage;
}

}  // namespace hexray::kernels
