// `fragpath view`: the interactive desktop viewer (a GLFW window; needs a display, or xvfb-run).
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "core/error.h"
#include "image/file_io.h"
#include "realtime/frame_budget.h"
#include "request/render_request.h"
#include "viewer/panel.h"
#include "viewer/viewer.h"

namespace fp {

namespace {

// The window is not one final image: its size is the window's, and it refines until stopped.
constexpr unsigned kViewOptions = kAllRequestOptions & ~kBackendOption;
const FrontEndDefaults kViewDefaults = FrontEndDefaults::ownImage({800, 600}, 0);

std::vector<OptionGroup> viewOptions() {
    return commandOptions(
        {{"Viewer",
          {{"--split", "", "NAME", "split view: the right half uses integrator NAME"},
           {"--split-depth", "", "D", "max depth of the right half (default: --max-depth)"},
           {"--denoise", "", "NAME",
            "none | bilateral | atrous: denoise the radiance view for display (N toggles\nraw / denoised; "
            "screenshots are of what is shown)"},
           {"--realtime", "", "",
            "start in real-time mode: a few samples per pixel each frame, reprojected history and the\n"
            "a-trous filter (the panel switches back to progressive)"},
           {"--fps", "", "N",
            "real-time mode's target frames per second, 1 to 240 (default " + std::to_string(kDefaultFps) +
                ")"},
           {"--dynamic-resolution", "", "on|off",
            "real-time mode: where one sample per pixel overruns the budget, render fewer pixels\n"
            "(halving their count per step, down to 1/8 of the side) and scale up (default on)"},
           {"--scale", "", "F", "accumulation size / window size, 0.0625 to 1 (default 1)"},
           {"--frames", "", "N",
            "close after N frames (with --spp S: not before S samples per pixel; never in the middle of a "
            "pass, so a screenshot holds whole passes) and print the median frame time and samples/s"},
           {"--screenshot", "", "FILE",
            "at exit, write the rendered image: .png as shown, .exr or .pfm linear"},
           {"--screenshot-window", "", "FILE", "at exit, write the whole window, panel included (.png)"},
           {"--no-ui", "", "", "no panel"}}}},
        kViewOptions, kViewDefaults);
}

void printViewUsage() {
    std::fputs(
        "usage: fragpath view [SCENE] [options]\n"
        "\n"
        "Opens a window that renders SCENE (an .obj with its .mtl, a glTF .gltf or .glb, or a .json scene\n"
        "file; default: the built-in Cornell box) progressively: the image refines while nothing changes\n"
        "and restarts when the camera or a setting does. A panel shows statistics and every setting. Needs\n"
        "a display; without one,\n"
        "run it as `xvfb-run -a fragpath view ...` or render offscreen with `fragpath render`. --size is "
        "the\n"
        "window's; --shader-dir also reloads the shaders when a *.glsl file there changes.\n",
        stdout);
    std::fputs(formatOptions(viewOptions()).c_str(), stdout);
    std::fputs("\ncontrols:\n", stdout);
    std::fputs(kViewerControlsHelp, stdout);
}

}  // namespace

int viewCommand(const std::vector<std::string>& argv) {
    Args args(argv, viewOptions());
    if (args.wantsHelp()) {
        printViewUsage();
        return 0;
    }
    const RenderRequest request(args, kViewDefaults);
    ViewerOptions options;
    options.frames = args.integer("--frames", 1, 1 << 30).value_or(0);
    options.printTiming = options.frames > 0;
    options.screenshot = args.text("--screenshot").value_or("");
    options.windowScreenshot = args.text("--screenshot-window").value_or("");
    if (!options.screenshot.empty()) checkImageOutput(options.screenshot, "--screenshot");
    if (!options.windowScreenshot.empty())
        checkImageOutput(options.windowScreenshot, "--screenshot-window", true);
    options.ui = !args.has("--no-ui");
    options.shaderDir = request.shaderDir();

    Scene scene = request.loadScene();
    ViewerControls& c = options.controls;
    c.render = request.settings(scene);
    options.windowSize = {c.render.width, c.render.height};
    if (auto s = args.text("--split")) {
        c.split = true;
        c.splitView.integrator = parseIntegrator(*s);
    }
    c.splitView.maxDepth = args.integer("--split-depth", 0, 1000).value_or(c.render.maxDepth);
    c.tone = request.display();
    if (auto name = args.text("--denoise")) c.denoiser = parseDenoiser(*name);
    c.realtime = args.has("--realtime");
    c.targetFps = args.integer("--fps", 1, 240).value_or(kDefaultFps);
    const std::string dynamic = args.text("--dynamic-resolution").value_or("on");
    if (dynamic != "on" && dynamic != "off")
        throw UsageError("option --dynamic-resolution: expected on or off, not '" + dynamic + "'");
    c.dynamicResolution = dynamic == "on";
    c.resolutionScale = args.number("--scale").value_or(1.0f);
    if (!(c.resolutionScale >= 1.0f / 16.0f && c.resolutionScale <= 1.0f))
        throw Error("option --scale: must be from 0.0625 to 1");
    c.targetSpp = request.spp(scene);
    options.camera = request.camera(scene);
    options.bvhThreads = request.bvhThreads();

    runViewer(scene, options);
    return 0;
}

}  // namespace fp
