#pragma once
#include <string>
#include <vector>

#include <epoxy/gl.h>

namespace patina {

// A linked GLSL 3.30 program assembled from embedded source parts (shaders/), with
// `defines` (e.g. "PATINA_SINGLE_PASS") placed after the #version line.
class GlProgram {
public:
    GlProgram(const std::vector<const char*>& vertexParts,
              const std::vector<const char*>& fragmentParts,
              const std::vector<std::string>& defines = {});
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }
    void use() const { glUseProgram(program_); }

private:
    GLuint program_ = 0;
};

}  // namespace patina
