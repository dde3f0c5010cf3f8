#include "request/render_request.h"

#include <cctype>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "gl/context.h"
#include "image/tone_map.h"
#include "scene/builtin_scene.h"
#include "scene/instancing.h"
#include "scene/lighting.h"
#include "scene/load.h"
#include "scene/studio_environment.h"

namespace fp {

namespace {

// A constant colour for --environment: a number, or three separated by commas ("0.5", "1,0.9,0.8"). A
// file name that starts with a digit is still a file when it has a map's extension.
bool looksLikeColor(const std::string& text) {
    if (text.empty() || isEnvironmentMapPath(text)) return false;
    const char c = text[0];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
}

// A setting's line in --help: the choices or range, the help text and the default.
Option settingOption(const Setting& setting, const FrontEndDefaults& defaults) {
    const RenderSettings d = defaults.settings();
    const bool fromScene = setting.sceneFile && !(defaults.ignoresSceneFile & setting.option);
    std::string value = settingText(setting, setting.get(d));
    if (isSizePart(setting)) value = std::to_string(d.width) + "x" + std::to_string(d.height);
    const std::string defaultText =
        "(default: " + std::string(fromScene ? "the scene file's, else " : "") + value + ")";
    // Choices first, with the default, then what they mean; else the help, then the default.
    if (setting.kind == SettingKind::Choice || setting.specialName)
        return {setting.flag, "", setting.valueName,
                settingChoices(setting) + " " + defaultText + "\n" + setting.help};
    return {setting.flag, "", setting.valueName, std::string(setting.help) + " " + defaultText};
}

}  // namespace

std::vector<OptionGroup> requestOptionGroups(unsigned options, const FrontEndDefaults& defaults) {
    OptionGroup image{"Image", {}}, scene{"Scene", {}}, path{"Path tracing", {}}, camera{"Camera", {}},
        display{"Display", {}}, gl{"OpenGL", {}};
    std::set<std::string> listed;  // flags shared by two settings (--size) are listed once
    for (const Setting& setting : settingTable()) {
        if (setting.hidden || !(options & setting.option) || !listed.insert(setting.flag).second) continue;
        OptionGroup& group = (setting.option & (kSizeOption | kSppOption)) ? image
                             : (setting.option & kViewOption)              ? display
                                                                           : path;
        group.options.push_back(settingOption(setting, defaults));
    }
    if (options & kSceneOptions) {
        scene.options.push_back(
            {"--environment", "", "ENV",
             "default | studio | none | X | R,G,B | FILE.hdr | FILE.exr\ndefault (if not given): the scene "
             "file's; a model with no light of its\nown (emitters that are only glowing detail do not count) "
             "gets the\nstudio environment, with a note | studio: that soft key, fill and\ngrey floor "
             "instead of the scene's | none: black, no environment |\nX or R,G,B: a constant sky of that "
             "radiance (1: the white furnace's) |\nFILE: that equirectangular map instead of the scene's"});
        scene.options.push_back(
            {"--strict", "", "",
             "every warning about repaired input (a missing texture, a dropped\ntriangle, ...) is "
             "an error: exit status 1 instead of a repaired render"});
        scene.options.push_back({"--flatten-instances", "", "",
                                 "store a glTF mesh that several nodes use once per node instead of\nonce "
                                 "(one BVH over every triangle, no two-level traversal)"});
    }
    if (options & kCameraOptions) {
        camera.options.push_back({"--eye", "", "X,Y,Z", "camera position"});
        camera.options.push_back({"--target", "", "X,Y,Z", "the point the camera looks at"});
        camera.options.push_back({"--up", "", "X,Y,Z", "the camera's up direction"});
        camera.options.push_back({"--fov", "", "DEG",
                                  "vertical field of view in degrees\n(each default: the scene file's "
                                  "camera, else one that frames the scene)"});
        camera.options.push_back({"--aperture", "", "A",
                                  "thin-lens depth of field: the lens diameter in scene units\n(default: "
                                  "the scene file's, else 0, a pinhole: everything sharp)"});
        camera.options.push_back({"--focus-distance", "", "F",
                                  "distance from the eye to the plane in focus, along the view\n(default: "
                                  "the scene file's, else the distance from eye to target)"});
    }
    if (options & kDisplayOptions) {
        display.options.push_back(
            {"--exposure", "", "STOPS", "scale by 2^STOPS before tone mapping (default 0)"});
        display.options.push_back({"--tonemap", "", "NAME", "clamp | reinhard | aces (default clamp)"});
    }
    if (options & kShaderOptions) {
        gl.options.push_back(
            {"--shader-dir", "", "DIR", "read the shaders from DIR instead of the ones built in"});
        gl.options.push_back({"--bvh-threads", "", "N",
                              "threads that build the BVH (default: every CPU); the tree is the same"});
    }
    if (options & kBackendOption)
        gl.options.push_back(
            {"--backend", "", "NAME",
             "auto (default: a GPU through EGL if there is one, else OSMesa) |\negl | osmesa"});
    std::vector<OptionGroup> groups;
    for (OptionGroup* g : {&image, &scene, &path, &camera, &display, &gl})
        if (!g->options.empty()) groups.push_back(std::move(*g));
    return groups;
}

std::vector<OptionGroup> commandOptions(std::vector<OptionGroup> own, unsigned shared,
                                        const FrontEndDefaults& defaults) {
    for (OptionGroup& g : requestOptionGroups(shared, defaults)) own.push_back(std::move(g));
    own.push_back(helpOptions());
    return own;
}

FrontEndDefaults FrontEndDefaults::ownImage(glm::ivec2 size, int spp) {
    FrontEndDefaults d;
    d.own.set("width", size.x);
    d.own.set("height", size.y);
    d.own.set("spp", spp);
    d.ignoresSceneFile = kSizeOption | kSppOption;
    return d;
}

RenderSettings FrontEndDefaults::settings() const {
    RenderSettings s;
    own.applyTo(s);
    return s;
}

RenderRequest::RenderRequest(const Args& args, const FrontEndDefaults& defaults) : defaults_(defaults) {
    if (defaults.scene && args.positional().size() > 1)
        throw Error("expected one scene file, got " + std::to_string(args.positional().size()) +
                    " arguments");
    if (defaults.scene && !args.positional().empty()) scenePath_ = args.positional()[0];
    for (const Setting& setting : settingTable()) {
        if (!*setting.flag) continue;
        if (isSizePart(setting)) {
            if (auto size = args.size(setting.flag))
                flags_.set(setting, std::string(setting.name) == "height" ? size->y : size->x);
        } else if (auto text = args.text(setting.flag)) {
            flags_.set(setting, parseSetting(setting, *text, std::string("option ") + setting.flag));
        }
    }
    eye_ = args.vec3("--eye");
    target_ = args.vec3("--target");
    up_ = args.vec3("--up");
    fov_ = args.number("--fov");
    aperture_ = args.number("--aperture");
    if (aperture_ && !(*aperture_ >= 0.0f))
        throw Error("option --aperture: must be 0 (a pinhole) or more (the lens diameter in scene units)");
    focusDistance_ = args.number("--focus-distance");
    if (focusDistance_ && !(*focusDistance_ > 0.0f))
        throw Error("option --focus-distance: must be above 0 (the distance to the plane in focus)");
    display_.exposure = args.number("--exposure").value_or(0.0f);
    if (auto t = args.text("--tonemap")) display_.toneMap = parseToneMap(*t);
    shaderDir_ = args.text("--shader-dir").value_or("");
    backend_ = args.text("--backend").value_or(kAutoBackend);
    bvhThreads_ = args.integer("--bvh-threads", 1, 1024).value_or(0);
    if (auto t = args.text("--environment")) {
        if (*t == "none") {
            environment_ = EnvironmentChoice::None;
        } else if (*t == "studio") {
            environment_ = EnvironmentChoice::Studio;
        } else if (looksLikeColor(*t)) {
            environment_ = EnvironmentChoice::Constant;
            environmentColor_ = t->find(',') != std::string::npos ? *args.vec3("--environment")
                                                                  : glm::vec3(*args.number("--environment"));
            for (int c = 0; c < 3; ++c)
                if (!(environmentColor_[c] >= 0.0f))
                    throw Error(
                        "option --environment: a colour's radiance is 0 or more in each channel, got '" + *t +
                        "'");
        } else if (*t != "default") {
            if (!isEnvironmentMapPath(*t))
                throw Error(
                    "option --environment: expected none, default, studio, a colour (X or R,G,B) or an .hdr "
                    "or "
                    ".exr file, got '" +
                    *t + "'");
            std::error_code ec;
            if (!std::filesystem::is_regular_file(*t, ec))
                throw Error("option --environment: " + *t + ": no such file");
            environment_ = EnvironmentChoice::Map;
            environmentMap_ = *t;
        }
    }
    strict_ = args.has("--strict");
    flattenInstances_ = args.has("--flatten-instances");
    setStrictWarnings(strict_);
}

Scene RenderRequest::loadScene() const {
    return prepareScene(scenePath_ ? fp::loadScene(*scenePath_) : builtinCornellBox());
}

Scene RenderRequest::prepareScene(Scene scene) const {
    if (flattenInstances_ && !scene.instances.empty()) scene = flattenInstances(std::move(scene));
    switch (environment_) {
        case EnvironmentChoice::Default:
            lightIfUnlit(scene, defaults_.defaultLight);
            break;
        case EnvironmentChoice::Studio:
            scene.environment = studioEnvironment();
            break;
        case EnvironmentChoice::Constant:
            scene.environment = Environment();
            scene.environment.color = environmentColor_;
            break;
        case EnvironmentChoice::None:
            scene.environment = Environment();
            break;
        case EnvironmentChoice::Map:
            scene.environment = Environment();
            scene.environment.map = loadEnvironmentMap(environmentMap_, "--environment " + environmentMap_);
            break;
    }
    return scene;
}

RenderSettings RenderRequest::settings(const Scene& scene) const {
    RenderSettings s = defaults_.settings();
    for (const Setting& setting : settingTable())
        if (auto value = scene.fileSettings.get(setting);
            value && !(defaults_.ignoresSceneFile & setting.option))
            setting.set(s, *value);
    flags_.applyTo(s);
    return s;
}

Camera RenderRequest::framingCamera(const Scene& scene) const {
    const RenderSettings s = settings(scene);
    return frameBounds(scene.bounds(), Camera().fovY, float(s.width) / float(s.height));
}

Camera RenderRequest::camera(const Scene& scene) const {
    Camera camera = scene.camera ? *scene.camera : framingCamera(scene);
    if (eye_) camera.eye = *eye_;
    if (target_) camera.target = *target_;
    if (up_) camera.up = *up_;
    if (fov_) camera.fovY = *fov_;
    if (aperture_) camera.aperture = *aperture_;
    if (focusDistance_) camera.focusDistance = *focusDistance_;
    validateCamera(camera, "camera");  // flags can break a valid scene camera
    return camera;
}

}  // namespace fp
