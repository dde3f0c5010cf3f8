#pragma once
// The one way this project includes OpenGL: glad's 4.1 core loader (third_party/glad).
#include <glad/gl.h>

namespace fp {

// One integer of glGetIntegerv (a limit such as GL_MAX_TEXTURE_SIZE); needs a current context.
inline GLint glInteger(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

}  // namespace fp
