#include "kernels/shader_compiler.h"

#include <mutex>
#include <string_view>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "kernels/shader_library_includer.h"
#include "shader_library.h"
#include "util/sha256.h"

namespace hexray::inline kernels {
namespace {

// What compileComputeShader targets (its setEnvClient and setEnvTarget), for the fingerprint; the
// kernel cache validates for the same (spirv_validation.h).
constexpr const char* kShaderTarget = "SPIR-V 1.3 for Vulkan 1.1";

void initializeGlslangOnce() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace

std::vector<std::uint32_t> compileComputeShader(const std::string& source, const std::string& name) {
    initializeGlslangOnce();
    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    ShaderLibraryIncluder includer;
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages, includer)) {
        throw ShaderCompileError(name + ": " + shader.getInfoLog());
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        throw ShaderCompileError(name + ": " + program.getInfoLog());
    }
    std::vector<std::uint32_t> spirv;
    glslang::SpvOptions options;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &options);
    return spirv;
}

ShaderCompilerWarmUp::ShaderCompilerWarmUp()
    : thread_([] {
          try {
              compileComputeShader("#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n", "warm-up");
          } catch (const std::exception&) {
              // Nothing is lost: the real compile reports its own problems.
          }
      }) {}

ShaderCompilerWarmUp::~ShaderCompilerWarmUp() {
    thread_.join();
}

const std::string& shaderCompilerFingerprint() {
    static const std::string fingerprint = [] {
        const glslang::Version version = glslang::GetVersion();
        std::string library;
        for (const shader_library::File& file : shader_library::kFiles) {
            library += std::to_string(file.name.size()) + ":" + std::string(file.name) +
                       std::to_string(file.text.size()) + ":" + std::string(file.text);
        }
        return "glslang " + std::to_string(version.major) + "." + std::to_string(version.minor) + "." +
               std::to_string(version.patch) + (version.flavor ? std::string("-") + version.flavor : "") + ", " +
               kShaderTarget + ", library " + sha256Hex(library);
    }();
    return fingerprint;
}

}  // namespace hexray::kernels
