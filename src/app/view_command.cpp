// `fragpath view`: the interactive desktop viewer (a GLFW window; needs a display, or xvfb-run).
#include <cstdio>
#include <string>

#include "app/args.h"
#include "app/commands.h"
#include "core/error.h"
#include "image/file_io.h"
#include "image/tone_map.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"
#include "viewer/panel.h"
#include "viewer/viewer.h"

namespace fp {

namespace {

const char* kViewUsage =
    "usage: fragpath view [SCENE] [options]\n"
    "\n"
    "Opens a window that renders SCENE (an .obj with its .mtl, or a .json scene file; default: the\n"
    "built-in Cornell box) progressively: the image refines while nothing changes and restarts when the\n"
    "camera or a setting does. A panel shows statistics and every setting. Needs a display; without one,\n"
    "run it as `xvfb-run -a fragpath view ...` or render offscreen with `fragpath render`.\n"
    "\n"
    "options:\n"
    "  --size WxH            window size (default 800x600)\n"
    "  --max-depth D         bounces (default: the scene file's, else 5)\n"
    "  --seed S              random seed (default: the scene file's, else 0)\n"
    "  --integrator NAME     naive | bsdf | nee | bdpt (default: the scene file's, else nee)\n"
    "  --sampler NAME        sobol (default) | independent: where the random numbers come from\n"
    "  --light-sampling NAME auto (default) | area | solid-angle: how nee samples points on emitters\n"
    "  --clamp-indirect X    clamp each sample's indirect light to X per channel (biased; off)\n"
    "  --view NAME           radiance | depth | normal | albedo | bounces | nodes | triangles | cost\n"
    "  --split NAME          split view: the right half uses integrator NAME\n"
    "  --split-depth D       max depth of the right half (default: --max-depth)\n"
    "  --eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov DEG\n"
    "                        home camera (default: the scene file's, else one that frames the scene)\n"
    "  --exposure STOPS      display exposure (default 0)\n"
    "  --tonemap NAME        clamp | reinhard | aces (default clamp)\n"
    "  --denoise NAME        none | bilateral | atrous: denoise the radiance view for display (N toggles\n"
    "                        raw / denoised; screenshots are of what is shown)\n"
    "  --scale F             accumulation size / window size, 0.0625 to 1 (default 1)\n"
    "  --spp N               stop rendering at N samples per pixel (default: never)\n"
    "  --shader-dir DIR      read shaders from DIR and reload them when a *.glsl file there changes\n"
    "  --frames N            close after N frames (with --spp S: not before S samples per pixel) and\n"
    "                        print the median frame time and samples/s\n"
    "  --screenshot FILE     at exit, write the rendered image: .png as shown, .exr or .pfm linear\n"
    "  --screenshot-window FILE\n"
    "                        at exit, write the whole window, panel included (.png)\n"
    "  --no-ui               no panel\n"
    "  -h, --help            this text\n"
    "\n"
    "controls:\n";

void checkImagePath(const std::string& flag, const std::string& path, bool pngOnly) {
    std::string ext = lowerCaseExtension(path);
    if (ext != ".png" && (pngOnly || (ext != ".exr" && ext != ".pfm")))
        throw Error("option " + flag + ": '" + path + "' must end in .png" +
                    (pngOnly ? "" : ", .exr or .pfm"));
}

}  // namespace

int viewCommand(const std::vector<std::string>& argv) {
    Args args(argv,
              {"--size",
               "--spp",
               "--max-depth",
               "--seed",
               "--integrator",
               "--sampler",
               "--light-sampling",
               "--clamp-indirect",
               "--view",
               "--split",
               "--split-depth",
               "--eye",
               "--target",
               "--up",
               "--fov",
               "--exposure",
               "--tonemap",
               "--scale",
               "--shader-dir",
               "--frames",
               "--screenshot",
               "--screenshot-window",
               "--denoise"},
              {"--no-ui", "-h", "--help"});
    if (args.has("-h") || args.has("--help")) {
        std::fputs(kViewUsage, stdout);
        std::fputs(kViewerControlsHelp, stdout);
        return 0;
    }
    if (args.positional().size() > 1)
        throw Error("view takes one scene file, got " + std::to_string(args.positional().size()));

    ViewerOptions options;
    if (auto s = args.size("--size")) options.windowSize = *s;
    options.frames = args.integer("--frames", 1, 1 << 30).value_or(0);
    options.printTiming = options.frames > 0;
    options.screenshot = args.text("--screenshot").value_or("");
    options.windowScreenshot = args.text("--screenshot-window").value_or("");
    if (!options.screenshot.empty()) checkImagePath("--screenshot", options.screenshot, false);
    if (!options.windowScreenshot.empty())
        checkImagePath("--screenshot-window", options.windowScreenshot, true);
    options.ui = !args.has("--no-ui");
    options.shaderDir = args.text("--shader-dir").value_or("");

    Scene scene = args.positional().empty() ? builtinCornellBox() : loadScene(args.positional()[0]);
    const RenderDefaults& d = scene.defaults;
    ViewerControls& c = options.controls;
    c.render.maxDepth = args.integer("--max-depth", 0, 1000).value_or(d.maxDepth.value_or(5));
    c.render.seed = uint32_t(args.integer("--seed", 0, 2147483647).value_or(int(d.seed.value_or(0))));
    c.render.integrator = parseIntegrator(args.text("--integrator").value_or(d.integrator.value_or("nee")));
    c.render.sampler =
        parseSampler(args.text("--sampler").value_or(d.sampler.value_or(samplerName(c.render.sampler))));
    if (auto l = args.text("--light-sampling")) c.render.lightSampling = parseLightSampling(*l);
    c.render.clampIndirect =
        args.number("--clamp-indirect").value_or(d.clampIndirect.value_or(c.render.clampIndirect));
    if (auto v = args.text("--view")) c.render.view = parseView(*v);
    if (auto s = args.text("--split")) {
        c.split = true;
        c.splitView.integrator = parseIntegrator(*s);
    }
    c.splitView.maxDepth = args.integer("--split-depth", 0, 1000).value_or(c.render.maxDepth);
    c.tone.exposure = args.number("--exposure").value_or(0.0f);
    if (auto t = args.text("--tonemap")) c.tone.toneMap = parseToneMap(*t);
    if (auto name = args.text("--denoise")) c.denoiser = parseDenoiser(*name);
    c.resolutionScale = args.number("--scale").value_or(1.0f);
    if (!(c.resolutionScale >= 1.0f / 16.0f && c.resolutionScale <= 1.0f))
        throw Error("option --scale: must be from 0.0625 to 1");
    c.targetSpp = args.integer("--spp", 1, 1 << 24).value_or(0);

    Camera camera = scene.camera.value_or(frameBounds(scene.bounds()));
    if (auto v = args.vec3("--eye")) camera.eye = *v;
    if (auto v = args.vec3("--target")) camera.target = *v;
    if (auto v = args.vec3("--up")) camera.up = *v;
    if (auto v = args.number("--fov")) camera.fovY = *v;
    validateCamera(camera, "camera");
    options.camera = camera;

    runViewer(scene, options);
    return 0;
}

}  // namespace fp
