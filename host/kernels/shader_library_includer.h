#pragma once
// glslang's includes resolved against the shader library embedded in hexray (shaders/*.glsl and the
// shared headers, cmake/embed_shader_library.cmake): what the compiler and the layout test read.

#include <glslang/Public/ShaderLang.h>

namespace hexray::inline kernels {

// Every include, local or system, is a file of the embedded library; anything else is not found.
class ShaderLibraryIncluder : public glslang::TShader::Includer {
public:
    IncludeResult* includeLocal(const char* name, const char*, size_t) override { return find(name); }
    IncludeResult* includeSystem(const char* name, const char*, size_t) override { return find(name); }
    void releaseInclude(IncludeResult* result) override { delete result; }

private:
    static IncludeResult* find(const char* name);
};

}  // namespace hexray::kernels
