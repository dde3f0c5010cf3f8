#pragma once
// An OpenGL 4.1+ core context made current on the calling thread, with functions loaded.
// The renderer only needs one to exist; the batch renderer uses OSMesa, the viewer a GLFW window.
#include <memory>
#include <string>

namespace fp {

class GlContext {
  public:
    virtual ~GlContext() = default;
    // "<GL_RENDERER>, OpenGL <GL_VERSION>" for --stats and logs.
    std::string description() const;
};

// Offscreen context on Mesa's OSMesa (llvmpipe): no display and no GPU needed.
// Throws fp::Error when no 4.1 core context can be created.
std::unique_ptr<GlContext> createOsMesaContext();

// Offscreen context through EGL's device platform, real GPUs first (no X server needed); with
// `requireHardware`, Mesa's software device does not count. Throws fp::Error when none works.
std::unique_ptr<GlContext> createEglContext(bool requireHardware);

// The default of --backend: an EGL GPU if there is one, else OSMesa.
constexpr const char* kAutoBackend = "auto";

// For --backend: "osmesa", "egl", or "auto" (kAutoBackend). Throws fp::Error
// for an unknown name or when the chosen backend fails.
std::unique_ptr<GlContext> createOffscreenContext(const std::string& backend);

// Loads GL functions through `getProc` and checks the version; throws fp::Error naming `who`.
using GlProcLoader = void* (*)(const char* name);
void loadGlFunctions(GlProcLoader getProc, const std::string& who);

}  // namespace fp
