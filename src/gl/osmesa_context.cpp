// OSMesa must be included after glad so that it does not pull in the system GL header.
#include "gl/gl.h"
// clang-format off
#include <GL/osmesa.h>
// clang-format on

#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/context.h"

namespace fp {

namespace {

class OsMesaContext : public GlContext {
  public:
    OsMesaContext() {
        // Mesa crashes inside OSMesaCreateContextAttribs when GALLIUM_DRIVER names a driver it lacks.
        const char* driver = std::getenv("GALLIUM_DRIVER");
        if (driver && std::string(driver) != "llvmpipe" && std::string(driver) != "softpipe")
            throw Error(std::string("OSMesa: GALLIUM_DRIVER=") + driver +
                        " is not a software driver OSMesa can use (unset it, or use llvmpipe)");
        // Core profile contexts are only offered through the attribute list; ask for the newest
        // version first and fall back to the 4.1 the shaders need.
        for (int minor : {5, 1}) {
            // clang-format off
            const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                                   OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                   OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, minor, 0};
            // clang-format on
            context_ = OSMesaCreateContextAttribs(attribs, nullptr);
            if (context_) break;
        }
        if (!context_) {
            std::string hint;
            for (const char* variable : {"MESA_GL_VERSION_OVERRIDE", "GALLIUM_DRIVER"})
                if (const char* value = std::getenv(variable))
                    hint += std::string("; ") + variable + "=" + value + " is set and may be the cause";
            throw Error("OSMesa: could not create an OpenGL 4.1 core context" + hint);
        }
        // OSMesa will not make a context current without a client buffer, even though all rendering
        // goes to framebuffer objects; a tiny one is enough.
        buffer_.resize(16 * 16 * 4);
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16)) {
            OSMesaDestroyContext(context_);
            throw Error("OSMesa: could not make the context current");
        }
        try {
            loadGlFunctions(reinterpret_cast<GlProcLoader>(OSMesaGetProcAddress), "OSMesa");
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext() {
    return std::make_unique<OsMesaContext>();
}

}  // namespace fp
