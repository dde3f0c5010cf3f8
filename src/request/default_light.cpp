#include "request/default_light.h"

#include <string>

#include "core/log.h"
#include "core/text.h"
#include "request/own_light.h"
#include "scene/lighting.h"
#include "scene/studio_environment.h"

namespace fp {

bool lightIfUnlit(Scene& scene, DefaultLight light) {
    if (hasPunctualOrEnvironmentLight(scene)) return false;
    std::string why = "no light of its own";
    if (hasEmitters(scene)) {
        const OwnLightEstimate own = estimateOwnLight(scene);
        if (own.lightsTheScene()) return false;
        why = formatText(
            "its emitters are glowing detail, not lighting (%.2f%% of their light stays in the "
            "scene, %.2fx the studio's light on its surfaces)",
            100.0 * own.enclosure, own.ownToStudio);
    }
    const bool studio = light == DefaultLight::Studio;
    note((scene.source.empty() ? std::string() : scene.source + ": ") + why + ": lit by " +
         (studio ? "the studio environment" : "a uniform white sky of radiance 1") +
         " (--environment none keeps it dark)");
    scene.environment = studio ? studioEnvironment() : defaultSky();
    return true;
}

}  // namespace fp
