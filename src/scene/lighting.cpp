#include "scene/lighting.h"

#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "image/exr.h"
#include "image/hdr.h"

namespace fp {

bool hasPunctualOrEnvironmentLight(const Scene& scene) {
    auto positive = [](const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; };
    // A black punctual light is left out of light selection (pack/pack.cpp): it lights nothing.
    for (const PunctualLight& l : scene.punctualLights)
        if (positive(l.intensity)) return true;
    const Environment& e = scene.environment;
    // Each as the renderer sees it (render/renderer.cpp): a colour unscaled, a map times its intensity.
    if (!e.hasMap()) return positive(e.color);
    if (!(e.intensity > 0.0f)) return false;
    for (const glm::vec3& p : e.map.pixels)
        if (positive(p)) return true;
    return false;
}

bool hasEmitters(const Scene& scene) {
    for (const Triangle& t : scene.triangles)
        if (t.material < scene.materials.size() && scene.materials[t.material].isEmissive()) return true;
    return false;
}

bool hasLight(const Scene& scene) {
    return hasEmitters(scene) || hasPunctualOrEnvironmentLight(scene);
}

Environment defaultSky() {
    Environment sky;
    sky.color = glm::vec3(1.0f);
    return sky;
}

bool isEnvironmentMapPath(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    return extension == ".hdr" || extension == ".exr";
}

Image loadEnvironmentMap(const std::string& path, const std::string& label) {
    if (!isEnvironmentMapPath(path)) throw Error(label + " must be a Radiance .hdr or an OpenEXR .exr file");
    Image map = lowerCaseExtension(path) == ".exr" ? readExrRadiance(path) : readHdr(path);
    size_t repaired = 0;
    for (glm::vec3& p : map.pixels)
        for (int c = 0; c < 3; ++c)
            if (!(std::isfinite(p[c]) && p[c] >= 0.0f)) {
                p[c] = 0.0f;
                ++repaired;
            }
    if (repaired > 0)
        warn(path + ": set " + std::to_string(repaired) + " negative or non-finite value" +
             (repaired == 1 ? "" : "s") +
             " of the environment map to 0 (radiance is finite and never negative)");
    return map;
}

}  // namespace fp
