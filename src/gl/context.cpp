#include "gl/context.h"

#include "core/error.h"
#include "gl/gl.h"

namespace fp {

static std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "?";
}

std::string GlContext::description() const {
    return glString(GL_RENDERER) + ", OpenGL " + glString(GL_VERSION);
}

std::unique_ptr<GlContext> createOffscreenContext(const std::string& backend) {
    if (backend == "osmesa") return createOsMesaContext();
    if (backend == "egl") return createEglContext(false);
    if (backend != kAutoBackend)
        throw Error("unknown backend '" + backend + "' (choose auto, egl or osmesa)");
    try {
        return createEglContext(true);
    } catch (const Error&) {
        return createOsMesaContext();  // no GPU reachable through EGL: software rendering
    }
}

void loadGlFunctions(GlProcLoader getProc, const std::string& who) {
    int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProc));
    if (version == 0) throw Error(who + ": could not load OpenGL functions");
    int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 4 || (major == 4 && minor < 1))
        throw Error(who + ": OpenGL 4.1 core is required, the context offers " + std::to_string(major) + "." +
                    std::to_string(minor) + " (" + glString(GL_RENDERER) + ")");
}

}  // namespace fp
