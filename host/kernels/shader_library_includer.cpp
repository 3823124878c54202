#include "kernels/shader_library_includer.h"

#include <string>

#include "shader_library.h"

namespace hexray::inline kernels {

glslang::TShader::Includer::IncludeResult* ShaderLibraryIncluder::find(const char* name) {
    for (const shader_library::File& file : shader_library::kFiles) {
        if (file.name == name) {
            return new IncludeResult(std::string(file.name), file.text.data(), file.text.size(), nullptr);
        }
    }
    return nullptr;  // glslang reports the include as not found
}

}  // namespace hexray::kernels
