#pragma once
// GLSL to SPIR-V at run time, with glslang's library (Debian's glslang-dev): how generated
// kernels are compiled. `#include "x.glsl"` resolves to the shader library embedded in hexray
// (shaders/*.glsl and shader_interface.h, see cmake/embed_shader_library.cmake).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexray {

class ShaderCompileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A compute shader's SPIR-V for Vulkan 1.1. Throws ShaderCompileError with glslang's log.
// Thread-safe.
std::vector<std::uint32_t> compileComputeShader(const std::string& source, const std::string& name);

// Changes whenever the same source could compile to different SPIR-V: glslang's version and the
// embedded library's text. Part of every kernel cache key.
const std::string& shaderCompilerFingerprint();

}  // namespace hexray
