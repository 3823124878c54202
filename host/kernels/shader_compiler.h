#pragma once
// GLSL to SPIR-V at run time, with glslang's library (Debian's glslang-dev): how generated
// kernels are compiled. `#include "x.glsl"` resolves to the shader library embedded in hexray
// (shaders/*.glsl and shader_interface.h, see cmake/embed_shader_library.cmake).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace hexray::inline kernels {

class ShaderCompileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A compute shader's SPIR-V for Vulkan 1.1. Throws ShaderCompileError with glslang's log.
// Thread-safe.
std::vector<std::uint32_t> compileComputeShader(const std::string& source, const std::string& name);

// Runs glslang's one-off set-up (its built-in symbol tables: tens of milliseconds, against a few for
// each compile after it) on another thread while the caller goes on, e.g. to create the Vulkan
// instance and device. Joined on destruction.
class ShaderCompilerWarmUp {
public:
    ShaderCompilerWarmUp();
    ~ShaderCompilerWarmUp();
    ShaderCompilerWarmUp(const ShaderCompilerWarmUp&) = delete;
    ShaderCompilerWarmUp& operator=(const ShaderCompilerWarmUp&) = delete;

private:
    std::thread thread_;
};

// Changes whenever the same source could compile to different SPIR-V: glslang's version, the
// SPIR-V and Vulkan versions targeted and the embedded library's text (its SHA-256). Part of every
// kernel cache key.
const std::string& shaderCompilerFingerprint();

}  // namespace hexray::kernels
