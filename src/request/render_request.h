#pragma once
// THE RENDER REQUEST: the one step that turns a command line, a scene file and the built-in defaults
// into what a render needs: the scene, its camera and the render settings. Every front end (render,
// view, study, bench, merge and fragpath_native) reads the options they share through it, so that a
// flag means the same everywhere and each default is written once.
//
// Precedence, highest first: a flag; the scene file ("render" block, "camera"); the front end's own
// default (FrontEndDefaults: a window, a sweep or a benchmark run is not one final image); the built-in
// default (RenderSettings in settings/render_settings.h, Camera framing the scene in scene/scene.h).
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "image/image.h"
#include "request/args.h"
#include "request/default_light.h"
#include "scene/lighting.h"
#include "scene/scene.h"
#include "settings/render_settings.h"
#include "settings/setting_table.h"

namespace fp {

// The shared options' bits (RequestOption) are in settings/setting_table.h, with the settings.

// What --environment asks for.
enum class EnvironmentChoice {
    Default,   // the scene's environment; a scene without light of its own gets the default light
               // (request/default_light.h lightIfUnlit)
    None,      // no environment at all: black wherever no surface is seen, whatever the scene file says
    Studio,    // the studio environment (scene/studio_environment.h), in place of the scene's
    Constant,  // a constant colour (X, a grey, or R,G,B), in place of the scene's environment
    Map,       // the map named on the command line, in place of the scene's environment
};

// Where a front end's defaults differ from one final render's.
struct FrontEndDefaults {
    // This front end's own defaults, over RenderSettings' (a window's size, a benchmark's spp and
    // samples per pass).
    SettingValues own;
    // RequestOption bits whose settings keep this front end's value whatever a scene file says (a
    // window's size; a benchmark's spp); flags still change them.
    unsigned ignoresSceneFile = 0;
    // The light of a scene without its own: the studio map, or the uniform sky for the native reference,
    // which has constant skies only.
    DefaultLight defaultLight = DefaultLight::Studio;
    bool scene = true;  // the positional argument names the scene (merge's are the parts it merges)

    // A window, a sweep or a benchmark run: its own size and spp (0: until stopped), whatever the scene
    // file says.
    static FrontEndDefaults ownImage(glm::ivec2 size, int spp);
    // The built-in defaults with this front end's over them.
    RenderSettings settings() const;
};

// The shared options a front end takes, grouped for its --help ("Image", "Path tracing", ...), with
// the defaults it applies.
std::vector<OptionGroup> requestOptionGroups(unsigned options, const FrontEndDefaults& defaults = {});

// A command's whole table: its own groups, the shared options it takes, then -h/--help.
std::vector<OptionGroup> commandOptions(std::vector<OptionGroup> own, unsigned shared,
                                        const FrontEndDefaults& defaults = {});

class RenderRequest {
  public:
    // Reads and checks every shared option in `args` (nothing is loaded yet, so a bad flag fails at
    // once); `args` refused the options its front end does not take (requestOptionGroups).
    explicit RenderRequest(const Args& args, const FrontEndDefaults& defaults = {});

    // The scene named on the command line (its only positional argument), else the built-in Cornell box,
    // with the environment --environment asks for: by default a scene without light of its own gets the
    // studio environment, with a note (request/default_light.h lightIfUnlit).
    Scene loadScene() const;
    // What loadScene does to the scene it loads (--flatten-instances, --environment), for a scene that
    // comes from elsewhere (the study's scene set).
    Scene prepareScene(Scene scene) const;
    const std::optional<std::string>& scenePath() const { return scenePath_; }

    // The settings table's loop: the built-in defaults, the front end's, the scene file's, the flags.
    RenderSettings settings(const Scene& scene) const;
    // Samples per pixel to reach; 0 for none.
    int spp(const Scene& scene) const { return settings(scene).spp; }
    // The scene's camera (its file's), else the default framing (scene/scene.h frameBounds) for the
    // image's aspect ratio, with the camera flags applied. Throws fp::Error when the flags make the
    // scene's camera invalid.
    Camera camera(const Scene& scene) const;

    DisplaySettings display() const { return display_; }
    const std::string& shaderDir() const { return shaderDir_; }
    const std::string& backend() const { return backend_; }
    int bvhThreads() const { return bvhThreads_; }  // 0: every CPU
    EnvironmentChoice environment() const { return environment_; }
    // --strict: every warning (fp::warn) is an error. The constructor sets core/log.h's strict mode to it.
    bool strict() const { return strict_; }

  private:
    Camera framingCamera(const Scene& scene) const;

    FrontEndDefaults defaults_;
    std::optional<std::string> scenePath_;
    SettingValues flags_;  // the settings the command line gives
    std::optional<glm::vec3> eye_, target_, up_;
    std::optional<float> fov_, aperture_, focusDistance_;
    DisplaySettings display_;
    std::string shaderDir_, backend_;
    int bvhThreads_ = 0;
    EnvironmentChoice environment_ = EnvironmentChoice::Default;
    std::string environmentMap_;        // with EnvironmentChoice::Map
    glm::vec3 environmentColor_{0.0f};  // with EnvironmentChoice::Constant
    bool strict_ = false;
    bool flattenInstances_ = false;
};

}  // namespace fp
