#pragma once
// A linked GLSL program built from two files of a ShaderLibrary, with cached uniform locations.
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"
#include "gl/shader_source.h"

namespace fp {

class Program {
  public:
    // Throws fp::Error with the compiler's log mapped to glsl/<file>:<line>.
    Program(const ShaderLibrary& library, const std::string& vertexPath, const std::string& fragmentPath,
            const ShaderDefines& defines = {});
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const { glUseProgram(id_); }
    GLuint id() const { return id_; }

    // Setters for the bound program; a uniform the compiler optimised away is ignored.
    void set(const char* name, int value);
    void set(const char* name, unsigned value);
    void set(const char* name, float value);
    void set(const char* name, const glm::vec2& value);
    void set(const char* name, const glm::vec3& value);
    void set(const char* name, const glm::ivec2& value);
    void set(const char* name, const std::vector<glm::vec4>& values);  // a vec4 array, from element 0

  private:
    GLint location(const char* name);
    GLuint id_ = 0;
    std::unordered_map<std::string, GLint> locations_;
};

}  // namespace fp
