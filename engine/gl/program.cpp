#include "gl/program.h"

#include <stdexcept>

namespace patina {

namespace {
std::string assemble(const std::vector<const char*>& parts, const std::vector<std::string>& defines) {
    // PATINA_INLINE marks shared functions `inline` for C++ (engine/shading/shading.h); GLSL has
    // none. `real` is the shared code's scalar, float on the GPU (shaders/shared/brdf.glsl).
    std::string source = "#version 330 core\n#define PATINA_INLINE\n#define real float\n";
    for (const std::string& define : defines) {
        source += "#define " + define + "\n";
    }
    for (const char* part : parts) {
        source += part;
        source += "\n";
    }
    return source;
}

GLuint compile(GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                 " shader failed to compile:\n" + log);
    }
    return shader;
}
}  // namespace

GlProgram::GlProgram(const std::vector<const char*>& vertexParts,
                     const std::vector<const char*>& fragmentParts,
                     const std::vector<std::string>& defines) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, assemble(vertexParts, defines));
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, assemble(fragmentParts, defines));
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, vertex);
    glAttachShader(program_, fragment);
    glLinkProgram(program_);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program_, length, nullptr, log.data());
        glDeleteProgram(program_);
        throw std::runtime_error("shader program failed to link:\n" + log);
    }
}

GlProgram::~GlProgram() {
    glDeleteProgram(program_);
}

}  // namespace patina
