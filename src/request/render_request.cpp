#include "request/render_request.h"

#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "core/log.h"
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

std::string sizeText(glm::ivec2 size) {
    return std::to_string(size.x) + "x" + std::to_string(size.y);
}

}  // namespace

std::vector<OptionGroup> requestOptionGroups(unsigned options, const FrontEndDefaults& defaults) {
    const RenderSettings builtIn;
    const std::string sceneOr = "the scene file's, else ";
    OptionGroup image{"Image", {}}, scene{"Scene", {}}, path{"Path tracing", {}}, camera{"Camera", {}},
        display{"Display", {}}, gl{"OpenGL", {}};
    if (options & kSizeOption)
        image.options.push_back({"--size", "", "WxH",
                                 "image size (default: " + (defaults.sceneSize ? sceneOr : std::string()) +
                                     sizeText(defaults.size) + ")"});
    if (options & kSppOption)
        image.options.push_back({"--spp", "", "N",
                                 "samples per pixel (default: " +
                                     (defaults.spp == 0 ? std::string("no limit")
                                                        : (defaults.sceneSpp ? sceneOr : std::string()) +
                                                              std::to_string(defaults.spp)) +
                                     ")"});
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
    if (options & kIntegratorOption)
        path.options.push_back({"--integrator", "", "NAME",
                                "naive | bsdf | nee | bdpt (default: " + sceneOr +
                                    integratorName(builtIn.integrator) +
                                    ")\nnee: light sampling with MIS; bdpt: bidirectional path tracing"});
    if (options & kPathOptions) {
        path.options.push_back({"--max-depth", "", "D",
                                "bounces: 0 shows emitters only, 1 direct light, ... (default: " + sceneOr +
                                    std::to_string(kDefaultMaxDepth) + ")"});
        path.options.push_back({"--seed", "", "S",
                                "random seed, 0 to " + std::to_string(kMaxSeed) +
                                    "; the same seed gives the same image bit for bit\n(default: " + sceneOr +
                                    std::to_string(builtIn.seed) + ")"});
    }
    if (options & kSamplingOptions) {
        path.options.push_back(
            {"--sampler", "", "NAME",
             "sobol: Owen-scrambled Sobol points, blue noise over the screen |\nindependent: "
             "independent uniform numbers (default: " +
                 sceneOr + samplerName(builtIn.sampler) + ")"});
        path.options.push_back(
            {"--light-sampling", "", "NAME",
             "auto: solid angle when an emitter faces a close surface | area |\nsolid-angle "
             "(nee: emitters over 0.1 sr by solid angle) (default: " +
                 sceneOr + lightSamplingName(builtIn.lightSampling) + ")"});
        path.options.push_back(
            {"--light-selection", "", "NAME",
             "auto: the tree for scenes of many emitters | power: by power |\ntree: by a light tree, "
             "power weighed by distance and orientation (nee)\n(default: " +
                 sceneOr + lightSelectionName(builtIn.lightSelection) + ")"});
        path.options.push_back(
            {"--caustics", "", "NAME",
             "auto: light where glass, mirrors or glossy metals meet a light | path:\ncamera paths "
             "alone | light: light paths traced to glass, mirrors and\nglossy metals, joined to the "
             "camera (nee) (default: " +
                 sceneOr + causticsName(builtIn.caustics) + ")"});
        path.options.push_back({"--clamp-indirect", "", "X",
                                "scale each sample's indirect light down to at most X per channel:\nfewer "
                                "fireflies, but BIASED (darker); not with bdpt (default: " +
                                    sceneOr + "off)"});
        path.options.push_back({"--samples-per-pass", "", "N",
                                "samples each pixel takes per draw call, 1 to " +
                                    std::to_string(RenderSettings::kMaxSamplesPerPass) +
                                    ", or auto: as many as fit a second (default " +
                                    samplesPerPassName(defaults.samplesPerPass) +
                                    "); the image is the same"});
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
    if (options & kViewOption)
        display.options.push_back(
            {"--view", "", "NAME",
             "radiance (default) | depth | normal | albedo: of the first hit |\nbounces | nodes | triangles: "
             "per primary ray, as a heat map |\ncost: nodes, triangles, surfaces per path in R, G, B"});
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
    d.size = size;
    d.sceneSize = false;
    d.spp = spp;
    d.sceneSpp = false;
    return d;
}

RenderRequest::RenderRequest(const Args& args, const FrontEndDefaults& defaults) : defaults_(defaults) {
    if (defaults.scene && args.positional().size() > 1)
        throw Error("expected one scene file, got " + std::to_string(args.positional().size()) +
                    " arguments");
    if (defaults.scene && !args.positional().empty()) scenePath_ = args.positional()[0];
    size_ = args.size("--size");
    spp_ = args.integer("--spp", 1, 1 << 24);
    maxDepth_ = args.integer("--max-depth", 0, 1000);
    if (auto s = args.integer("--seed", 0, int(kMaxSeed))) seed_ = uint32_t(*s);
    if (auto t = args.text("--integrator")) integrator_ = parseIntegrator(*t);
    if (auto t = args.text("--sampler")) sampler_ = parseSampler(*t);
    if (auto t = args.text("--light-sampling")) lightSampling_ = parseLightSampling(*t);
    if (auto t = args.text("--light-selection")) lightSelection_ = parseLightSelection(*t);
    if (auto t = args.text("--caustics")) caustics_ = parseCaustics(*t);
    clampIndirect_ = args.number("--clamp-indirect");
    if (clampIndirect_ && !(*clampIndirect_ >= 0.0f))
        throw Error("option --clamp-indirect: must be 0 (off) or more");
    if (args.text("--samples-per-pass") == "auto")
        samplesPerPass_ = RenderSettings::kAutoSamplesPerPass;
    else
        samplesPerPass_ = args.integer("--samples-per-pass", 1, RenderSettings::kMaxSamplesPerPass);
    if (auto t = args.text("--view")) view_ = parseView(*t);
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
    backend_ = args.text("--backend").value_or("auto");
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
    const RenderDefaults& file = scene.defaults;
    RenderSettings s;
    glm::ivec2 size = defaults_.size;
    if (defaults_.sceneSize && file.width) size.x = *file.width;
    if (defaults_.sceneSize && file.height) size.y = *file.height;
    size = size_.value_or(size);
    s.width = size.x;
    s.height = size.y;
    s.maxDepth = maxDepth_.value_or(file.maxDepth.value_or(s.maxDepth));
    s.seed = seed_.value_or(file.seed.value_or(s.seed));
    s.integrator = integrator_.value_or(file.integrator.value_or(s.integrator));
    s.sampler = sampler_.value_or(file.sampler.value_or(s.sampler));
    s.lightSampling = lightSampling_.value_or(file.lightSampling.value_or(s.lightSampling));
    s.lightSelection = lightSelection_.value_or(file.lightSelection.value_or(s.lightSelection));
    s.caustics = caustics_.value_or(file.caustics.value_or(s.caustics));
    s.clampIndirect = clampIndirect_.value_or(file.clampIndirect.value_or(s.clampIndirect));
    s.samplesPerPass = samplesPerPass_.value_or(defaults_.samplesPerPass);
    s.view = view_.value_or(s.view);
    return s;
}

int RenderRequest::spp(const Scene& scene) const {
    if (spp_) return *spp_;
    if (defaults_.sceneSpp && scene.defaults.spp) return *scene.defaults.spp;
    return defaults_.spp;
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
