// Headless OpenGL through EGL: on a GPU server without X, EGL reaches the GPU directly (the device
// platform); on a machine without one it finds Mesa's software device, the same llvmpipe OSMesa uses.
#include "gl/gl.h"
// clang-format off
#include <EGL/egl.h>
#include <EGL/eglext.h>
// clang-format on

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/context.h"

namespace fp {

namespace {

class EglContext : public GlContext {
  public:
    explicit EglContext(EGLDisplay display) : display_(display) {
        const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config;
        EGLint count = 0;
        if (!eglChooseConfig(display_, configAttribs, &config, 1, &count) || count < 1)
            fail("no EGL configuration for offscreen OpenGL");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL cannot bind the desktop OpenGL API");
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         1,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
        if (context_ == EGL_NO_CONTEXT) fail("could not create an OpenGL 4.1 core context");
        // All rendering goes to framebuffer objects, but not every driver allows no surface at all.
        const EGLint pbufferAttribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
        surface_ = eglCreatePbufferSurface(display_, config, pbufferAttribs);
        if (!eglMakeCurrent(display_, surface_, surface_, context_))
            fail("could not make the context current");
        loadGlFunctions(reinterpret_cast<GlProcLoader>(eglGetProcAddress), "EGL");
    }
    ~EglContext() override { release(); }

  private:
    [[noreturn]] void fail(const std::string& what) {
        release();
        throw Error("EGL: " + what + " (error 0x" + hex(eglGetError()) + ")");
    }
    static std::string hex(EGLint v) {
        char text[16];
        std::snprintf(text, sizeof text, "%04x", unsigned(v));
        return text;
    }
    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
        display_ = EGL_NO_DISPLAY;
    }
    EGLDisplay display_;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
};

struct Device {
    EGLDeviceEXT device;
    bool hardware;  // has a DRM device file: a real GPU, not Mesa's software device
};

std::vector<Device> eglDevices() {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (!queryDevices || !queryDeviceString) return {};
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices(16, devices, &count)) return {};
    std::vector<Device> out;
    for (EGLint i = 0; i < count; ++i) {
        const char* extensions = queryDeviceString(devices[i], EGL_EXTENSIONS);
        bool drm = extensions && std::string(extensions).find("EGL_EXT_device_drm") != std::string::npos &&
                   queryDeviceString(devices[i], EGL_DRM_DEVICE_FILE_EXT) != nullptr;
        out.push_back({devices[i], drm});
    }
    // Real GPUs first.
    std::stable_partition(out.begin(), out.end(), [](const Device& d) { return d.hardware; });
    return out;
}

}  // namespace

std::unique_ptr<GlContext> createEglContext(bool requireHardware) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay)
        throw Error("EGL: eglGetPlatformDisplayEXT is not available (is libEGL installed?)");
    std::string tried;
    for (const Device& d : eglDevices()) {
        if (requireHardware && !d.hardware) continue;
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, d.device, nullptr);
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
            tried += " a device that would not initialise;";
            continue;
        }
        try {
            return std::make_unique<EglContext>(display);
        } catch (const Error& e) {
            tried += std::string(" ") + e.what() + ";";
        }
    }
    throw Error(std::string("EGL: no ") + (requireHardware ? "GPU " : "") +
                "device gave an OpenGL 4.1 core context" +
                (tried.empty() ? " (no EGL devices found)" : ":" + tried));
}

}  // namespace fp
