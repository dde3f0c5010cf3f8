// The render request's precedence, field by field: a flag, else the scene file, else the front end's
// default, else the built-in one.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/log.h"
#include "request/render_request.h"
#include "scene/studio_environment.h"

namespace fp {
namespace {

RenderRequest request(const std::vector<std::string>& argv, const FrontEndDefaults& defaults = {},
                      unsigned options = kAllRequestOptions) {
    return RenderRequest(Args(argv, requestOptionGroups(options, defaults)), defaults);
}

// The message a request for `argv` fails with, "no error" if it does not.
std::string message(const std::vector<std::string>& argv) {
    try {
        request(argv);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// A scene as a scene file leaves it: every default and a camera set, each unlike the built-in one.
Scene sceneWithDefaults() {
    Scene scene;
    scene.triangles.push_back({});
    scene.fileSettings.set("width", 320);
    scene.fileSettings.set("height", 240);
    scene.fileSettings.set("spp", 7);
    scene.fileSettings.set("max_depth", 2);
    scene.fileSettings.set("seed", 9u);
    scene.fileSettings.set("integrator", int(Integrator::Bsdf));
    scene.fileSettings.set("sampler", int(Sampler::Independent));
    scene.fileSettings.set("light_sampling", int(LightSampling::Area));
    scene.fileSettings.set("clamp_indirect", 3.0f);
    Camera camera;
    camera.eye = {0, 0, 5};
    camera.fovY = 50.0f;
    camera.aperture = 0.5f;
    camera.focusDistance = 4.0f;
    scene.camera = camera;
    return scene;
}

TEST(RenderRequest, WithNothingGivenTheBuiltInDefaultsApply) {
    const RenderSettings builtIn;
    Scene bare;
    bare.triangles.push_back({});
    RenderSettings s = request({}).settings(bare);
    EXPECT_EQ(s.width, 512);
    EXPECT_EQ(s.maxDepth, kDefaultMaxDepth);
    EXPECT_EQ(s.seed, builtIn.seed);
    EXPECT_EQ(s.integrator, builtIn.integrator);
    EXPECT_EQ(s.sampler, builtIn.sampler);
    EXPECT_EQ(s.lightSampling, builtIn.lightSampling);
    EXPECT_EQ(s.clampIndirect, builtIn.clampIndirect);
    EXPECT_EQ(request({}).spp(bare), 64);
}

TEST(RenderRequest, TheSceneFileOverridesTheDefaults) {
    Scene scene = sceneWithDefaults();
    RenderRequest r = request({});
    RenderSettings s = r.settings(scene);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);
    EXPECT_EQ(s.maxDepth, 2);
    EXPECT_EQ(s.seed, 9u);
    EXPECT_EQ(s.integrator, Integrator::Bsdf);
    EXPECT_EQ(s.sampler, Sampler::Independent);
    EXPECT_EQ(s.lightSampling, LightSampling::Area);
    EXPECT_EQ(s.clampIndirect, 3.0f);
    EXPECT_EQ(r.spp(scene), 7);
    EXPECT_EQ(r.camera(scene).eye, glm::vec3(0, 0, 5));
    EXPECT_EQ(r.camera(scene).fovY, 50.0f);
    EXPECT_EQ(r.camera(scene).aperture, 0.5f);
    EXPECT_EQ(r.camera(scene).focusDistance, 4.0f);
}

// --aperture and --focus-distance: a flag over the scene file over the default (a pinhole focused on the
// target), each on its own.
TEST(RenderRequest, TheLensTakesFlagsOverTheSceneFileOverTheDefault) {
    Scene bare;
    bare.triangles.push_back({});
    Camera framed = request({}).camera(bare);
    EXPECT_EQ(framed.aperture, 0.0f);
    EXPECT_FALSE(framed.focusDistance.has_value());
    EXPECT_FLOAT_EQ(resolvedFocusDistance(framed), glm::length(framed.target - framed.eye));
    Camera flagged = request({"--aperture", "2", "--eye", "0,0,-7"}).camera(bare);
    EXPECT_EQ(flagged.aperture, 2.0f);
    EXPECT_EQ(resolvedFocusDistance(flagged), 7.0f) << "the default follows the eye and target as flagged";

    Scene scene = sceneWithDefaults();
    Camera c = request({"--aperture=0.125"}).camera(scene);
    EXPECT_EQ(c.aperture, 0.125f);
    EXPECT_EQ(c.focusDistance, 4.0f);  // the file's
    c = request({"--focus-distance", "9.5"}).camera(scene);
    EXPECT_EQ(c.aperture, 0.5f);  // the file's
    EXPECT_EQ(c.focusDistance, 9.5f);
    c = request({"--aperture", "0"}).camera(scene);
    EXPECT_EQ(c.aperture, 0.0f) << "a flag can turn the file's lens into a pinhole";
}

TEST(RenderRequest, BadLensFlagsFailWithClearMessages) {
    EXPECT_EQ(message({"--aperture", "-1"}),
              "option --aperture: must be 0 (a pinhole) or more (the lens diameter in scene units)");
    EXPECT_EQ(message({"--focus-distance", "0"}),
              "option --focus-distance: must be above 0 (the distance to the plane in focus)");
    EXPECT_EQ(message({"--focus-distance", "-3"}),
              "option --focus-distance: must be above 0 (the distance to the plane in focus)");
    EXPECT_EQ(message({"--aperture", "inf"}), "option --aperture: 'inf' is not a finite number");
    EXPECT_EQ(message({"--focus-distance", "near"}),
              "option --focus-distance: 'near' is not a finite number");
    EXPECT_EQ(message({"--aperture", "0.5", "--focus-distance", "12"}), "no error");
}

TEST(RenderRequest, FlagsOverrideTheSceneFile) {
    Scene scene = sceneWithDefaults();
    RenderRequest r = request({"--size=64x32",
                               "--spp",
                               "3",
                               "--max-depth",
                               "4",
                               "--seed",
                               "11",
                               "--integrator",
                               "naive",
                               "--sampler",
                               "sobol",
                               "--light-sampling",
                               "solid-angle",
                               "--clamp-indirect",
                               "0",
                               "--samples-per-pass",
                               "4",
                               "--view",
                               "depth",
                               "--eye",
                               "1,2,3",
                               "--fov",
                               "30"});
    RenderSettings s = r.settings(scene);
    EXPECT_EQ(s.width, 64);
    EXPECT_EQ(s.height, 32);
    EXPECT_EQ(s.maxDepth, 4);
    EXPECT_EQ(s.seed, 11u);
    EXPECT_EQ(s.integrator, Integrator::Naive);
    EXPECT_EQ(s.sampler, Sampler::Sobol);
    EXPECT_EQ(s.lightSampling, LightSampling::SolidAngle);
    EXPECT_EQ(s.clampIndirect, 0.0f);
    EXPECT_EQ(s.samplesPerPass, 4);
    EXPECT_EQ(request({"--samples-per-pass", "auto"}).settings(scene).samplesPerPass,
              RenderSettings::kAutoSamplesPerPass);
    EXPECT_EQ(request({}).settings(scene).samplesPerPass, RenderSettings::kAutoSamplesPerPass);
    EXPECT_EQ(s.view, View::Depth);
    EXPECT_EQ(r.spp(scene), 3);
    Camera c = r.camera(scene);
    EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.target, glm::vec3(0));  // not given: the scene file's
    EXPECT_EQ(c.fovY, 30.0f);
}

TEST(RenderRequest, AFrontEndCanKeepItsOwnSizeAndSpp) {
    FrontEndDefaults window = FrontEndDefaults::ownImage({800, 600}, 0);
    Scene scene = sceneWithDefaults();
    RenderRequest r = request({}, window);
    EXPECT_EQ(r.settings(scene).width, 800);
    EXPECT_EQ(r.settings(scene).height, 600);
    EXPECT_EQ(r.spp(scene), 0);
    EXPECT_EQ(r.settings(scene).maxDepth, 2);  // the rest of the scene file still applies
    EXPECT_EQ(request({"--size", "100x50"}, window).settings(scene).width, 100);
}

TEST(RenderRequest, AFrontEndRefusesTheOptionsItDoesNotTake) {
    EXPECT_THROW(request({"--backend", "egl"}, {}, kAllRequestOptions & ~kBackendOption), Error);
    EXPECT_THROW(request({"--spp", "4"}, {}, kDisplayOptions), Error);
    EXPECT_NO_THROW(request({"--exposure", "-1"}, {}, kDisplayOptions));
}

TEST(RenderRequest, BadValuesFailBeforeAnythingIsLoaded) {
    EXPECT_THROW(request({"--integrator", "path"}), Error);
    EXPECT_THROW(request({"--seed", "2147483648"}), Error);
    EXPECT_THROW(request({"--clamp-indirect", "-1"}), Error);
    EXPECT_THROW(request({"a.obj", "b.obj"}), Error);
    EXPECT_EQ(request({"--seed", "2147483647"}).settings(Scene()).seed, kMaxSeed);
    // A flag can break the scene file's camera: the request says so.
    Scene scene = sceneWithDefaults();
    EXPECT_THROW(request({"--eye", "0,0,0", "--target", "0,0,0"}).camera(scene), Error);
}

TEST(RenderRequest, TheSceneIsThePositionalArgumentUnlessTheFrontEndSaysOtherwise) {
    EXPECT_EQ(request({"room.obj"}).scenePath(), std::optional<std::string>("room.obj"));
    EXPECT_FALSE(request({}).scenePath());
    FrontEndDefaults merge;
    merge.scene = false;
    EXPECT_FALSE(request({"a.exr", "b.exr"}, merge, kDisplayOptions).scenePath());
}

// A scene without a camera is framed for the image's aspect ratio (scene/scene.h frameBounds): a wide
// model in a wide image is seen from closer than in a tall one, where its width must fit the narrow
// horizontal field of view.
TEST(RenderRequest, TheDefaultFramingFitsTheImagesAspectRatio) {
    Scene wide;
    wide.materials.push_back(Material{});
    Triangle t;
    t.p = {glm::vec3(-10, 0, 0), glm::vec3(10, 0, 0), glm::vec3(0, 1, 0)};
    wide.triangles.push_back(t);
    const Camera inWide = request({"--size", "400x100"}).camera(wide);
    const Camera inTall = request({"--size", "100x400"}).camera(wide);
    EXPECT_EQ(inWide.eye, frameBounds(wide.bounds(), 40.0f, 4.0f).eye);
    EXPECT_EQ(inTall.eye, frameBounds(wide.bounds(), 40.0f, 0.25f).eye);
    EXPECT_LT(glm::length(inWide.eye - inWide.target), 0.5f * glm::length(inTall.eye - inTall.target));
    // A camera flag still overrides the framing's.
    EXPECT_EQ(request({"--size", "400x100", "--eye", "0,0,-7"}).camera(wide).eye, glm::vec3(0, 0, -7));
}

// What each --environment choice does to a scene without light (one Lambertian triangle).
TEST(RenderRequest, EnvironmentChoicesLightAScene) {
    Scene bare;
    bare.materials.push_back(Material{});
    Triangle t;
    t.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    bare.triangles.push_back(t);
    WarningCapture capture;
    Scene byDefault = request({}).prepareScene(bare);
    EXPECT_EQ(byDefault.environment.map.pixels, studioEnvironment().map.pixels);
    EXPECT_EQ(capture.notes().size(), 1u);
    EXPECT_EQ(request({"--environment", "studio"}).prepareScene(bare).environment.map.pixels,
              studioEnvironment().map.pixels);
    Scene grey = request({"--environment", "0.5"}).prepareScene(bare);
    EXPECT_FALSE(grey.environment.hasMap());
    EXPECT_EQ(grey.environment.color, glm::vec3(0.5f));
    EXPECT_EQ(request({"--environment", "1,0.9,0.8"}).prepareScene(bare).environment.color,
              glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_TRUE(request({"--environment", "none"}).prepareScene(bare).environment.isBlack());
    FrontEndDefaults native;
    native.defaultLight = DefaultLight::UniformSky;
    EXPECT_EQ(request({}, native).prepareScene(bare).environment.color, glm::vec3(1.0f));
    EXPECT_TRUE(capture.messages().empty()) << "notes only";
}

TEST(RenderRequest, EnvironmentAndStrictAreReadAndCheckedAtOnce) {
    EXPECT_EQ(request({}).environment(), EnvironmentChoice::Default);
    EXPECT_EQ(request({"--environment", "default"}).environment(), EnvironmentChoice::Default);
    EXPECT_EQ(request({"--environment=none"}).environment(), EnvironmentChoice::None);
    // A map must be an .hdr or .exr that exists, before any scene is loaded.
    EXPECT_EQ(
        message({"--environment", "black"}),
        "option --environment: expected none, default, studio, a colour (X or R,G,B) or an .hdr or .exr "
        "file, got 'black'");
    EXPECT_EQ(message({"--environment", "/no/such/sky.exr"}),
              "option --environment: /no/such/sky.exr: no such file");
    EXPECT_THROW(request({"--environment", "none"}, {}, kAllRequestOptions & ~kSceneOptions), UsageError);
    // The studio environment and constant colours: a grey X or R,G,B, finite and 0 or more.
    EXPECT_EQ(request({"--environment", "studio"}).environment(), EnvironmentChoice::Studio);
    EXPECT_EQ(request({"--environment", "0.5"}).environment(), EnvironmentChoice::Constant);
    EXPECT_EQ(request({"--environment", "1,0.9,0.8"}).environment(), EnvironmentChoice::Constant);
    EXPECT_EQ(message({"--environment", "-1"}),
              "option --environment: a colour's radiance is 0 or more in each channel, got '-1'");
    EXPECT_EQ(message({"--environment", "1,-0.5,1"}),
              "option --environment: a colour's radiance is 0 or more in each channel, got '1,-0.5,1'");
    EXPECT_EQ(message({"--environment", "1,2"}), "option --environment: expected X,Y,Z, got '1,2'");
    EXPECT_EQ(message({"--environment", "0.5x"}), "option --environment: '0.5x' is not a finite number");
    EXPECT_EQ(message({"--environment", "1e99"}), "option --environment: '1e99' is not a finite number");

    // --strict sets core/log's strict mode, and a request without it clears it.
    EXPECT_TRUE(request({"--strict"}).strict());
    EXPECT_TRUE(strictWarnings());
    EXPECT_THROW(warn("a repaired thing"), Error);
    EXPECT_FALSE(request({}).strict());
    EXPECT_FALSE(strictWarnings());
    WarningCapture capture;
    warn("a repaired thing");
    EXPECT_TRUE(capture.contains("a repaired thing"));
}

}  // namespace
}  // namespace fp
