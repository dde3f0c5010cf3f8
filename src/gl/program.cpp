#include "gl/program.h"

#include "core/error.h"

namespace fp {

static std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(length > 0 ? length : 1), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

static GLuint compile(GLenum stage, const ShaderLibrary& library, const std::string& path,
                      const ShaderDefines& defines) {
    ExpandedShader source = library.expand(path, defines);
    GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log = mapCompileLog(infoLog(shader, false), source);
        glDeleteShader(shader);
        throw Error("shader compilation failed (glsl/" + path + "):\n" + log);
    }
    return shader;
}

Program::Program(const ShaderLibrary& library, const std::string& vertexPath, const std::string& fragmentPath,
                 const ShaderDefines& defines) {
    GLuint vertex = compile(GL_VERTEX_SHADER, library, vertexPath, defines);
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, library, fragmentPath, defines);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vertex);
    glAttachShader(id_, fragment);
    glLinkProgram(id_);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = infoLog(id_, true);
        glDeleteProgram(id_);
        throw Error("shader link failed (glsl/" + vertexPath + " + glsl/" + fragmentPath + "):\n" + log);
    }
}

Program::~Program() {
    glDeleteProgram(id_);
}

GLint Program::location(const char* name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(id_, name);
    locations_.emplace(name, loc);
    return loc;
}

void Program::set(const char* name, int value) {
    glUniform1i(location(name), value);
}
void Program::set(const char* name, unsigned value) {
    glUniform1ui(location(name), value);
}
void Program::set(const char* name, float value) {
    glUniform1f(location(name), value);
}
void Program::set(const char* name, const glm::vec2& v) {
    glUniform2f(location(name), v.x, v.y);
}
void Program::set(const char* name, const glm::vec3& v) {
    glUniform3f(location(name), v.x, v.y, v.z);
}
void Program::set(const char* name, const glm::ivec2& v) {
    glUniform2i(location(name), v.x, v.y);
}
void Program::set(const char* name, const std::vector<glm::vec4>& values) {
    if (!values.empty()) glUniform4fv(location(name), GLsizei(values.size()), &values[0].x);
}

}  // namespace fp
