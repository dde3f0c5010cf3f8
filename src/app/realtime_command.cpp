// `fragpath realtime`: the viewer's real-time pipeline, headless, along a camera path (realtime/).
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/error.h"
#include "core/text.h"
#include "gl/context.h"
#include "pack/layout.h"
#include "realtime/camera_path.h"
#include "realtime/frame_budget.h"
#include "realtime/realtime_run.h"
#include "request/render_request.h"

namespace fp {

namespace {

constexpr unsigned kRealtimeOptions = kAllRequestOptions & ~kViewOption;
const FrontEndDefaults kRealtimeDefaults = FrontEndDefaults::ownImage({256, 256}, 0);

std::vector<OptionGroup> realtimeOptions() {
    return commandOptions(
        {{"Real time",
          {{"--camera-path", "", "orbit|FILE",
            "orbit: the eye circles the camera's target about its up axis (--orbit-speed); FILE.json: "
            "keyframes {\"keyframes\": [{\"time\", \"eye\", \"target\", \"up\", \"fov\"}, ...]} (default "
            "orbit)"},
           {"--orbit-speed", "", "DEG",
            "degrees per second of the orbit (default " + formatText("%g", kDefaultOrbitDegreesPerSecond) +
                ")"},
           {"--frames", "", "N", "frames to render (default 60)"},
           {"--fps", "", "F",
            "frames per second: frame i shows the path at i / F s, and 1000 / F ms is the budget the samples "
            "per frame are fitted to (default " +
                std::to_string(kDefaultFps) + ")"},
           {"--temporal", "", "on|off", "reuse the reprojected history (default on)"},
           {"--filter", "", "atrous|none", "the spatial filter after reprojection (default atrous)"},
           {"--settled", "", "N",
            "pixels whose history holds N samples or more skip the filter: their mean is already clean "
            "(default 16; 0: every pixel is filtered)"},
           {"--max-history", "", "N",
            "samples per pixel the history keeps while the camera moves (default 32)"},
           {"--reference-spp", "", "K",
            "also render each frame's view with K samples and write its error (rmse, rel_mse, ssim, "
            "HDR-FLIP) and flicker against it to frames.csv"},
           {"--reference-cache", "", "DIR",
            "keep the references in DIR (EXR) and reuse them in later runs of the same scene, settings and "
            "camera path (other settings or another path there are an error)"},
           {"--out", "", "DIR", "where frame_NNNN.png and frames.csv go (required)"}}}},
        kRealtimeOptions, kRealtimeDefaults);
}

void printRealtimeUsage() {
    std::fputs(
        "usage: fragpath realtime [SCENE] --out DIR [options]\n"
        "\n"
        "Renders a camera path frame by frame as the viewer's real-time mode does: each frame traces the\n"
        "samples that fit the frame budget (or --spp per frame), reprojects the previous frames' history\n"
        "(rejected where the first hit's depth, normal or kind disagree) and filters it with the\n"
        "variance-guided a-trous filter. Writes DIR/frame_NNNN.png and DIR/frames.csv, one row per frame:\n"
        "frame,ms,spp,trace_ms,temporal_ms,filter_ms,mean_history_frames,rmse,rel_mse,ssim,flip,flicker\n"
        "(the error columns with --reference-spp; flicker from the second frame: the mean change of the\n"
        "display luma's error from one frame to the next, or of the luma itself without references).\n"
        "DIR/strip.png shows five frames spread over the run, above their references. Interrupted, it\n"
        "keeps the frames written so far.\n",
        stdout);
    std::fputs(formatOptions(realtimeOptions()).c_str(), stdout);
}

bool onOff(const Args& args, const std::string& flag) {
    std::string v = args.text(flag).value_or("on");
    if (v != "on" && v != "off") throw UsageError("option " + flag + ": expected on or off, not '" + v + "'");
    return v == "on";
}

volatile std::sig_atomic_t gInterrupted = 0;
void onInterrupt(int) {
    gInterrupted = 1;
}

}  // namespace

int realtimeCommand(const std::vector<std::string>& argv) {
    Args args(argv, realtimeOptions());
    if (args.wantsHelp()) {
        printRealtimeUsage();
        return 0;
    }
    const RenderRequest request(args, kRealtimeDefaults);
    auto out = args.text("--out");
    if (!out) throw UsageError("realtime needs --out DIR for its frames and frames.csv");
    const std::string pathName = args.text("--camera-path").value_or("orbit");
    const double orbitSpeed = args.number("--orbit-speed").value_or(float(kDefaultOrbitDegreesPerSecond));
    const int frames = args.integer("--frames", 1, 1000000).value_or(60);
    const float fps = args.number("--fps").value_or(float(kDefaultFps));
    if (!(fps > 0.0f && fps <= 1000.0f)) throw UsageError("option --fps: expected a rate in (0, 1000]");
    TemporalSettings temporal;
    temporal.reuse = onOff(args, "--temporal");
    std::string filter = args.text("--filter").value_or("atrous");
    if (filter != "atrous" && filter != "none")
        throw UsageError("option --filter: expected atrous or none, not '" + filter + "'");
    temporal.filter = filter == "atrous" ? Denoiser::Atrous : Denoiser::None;
    temporal.maxHistorySamples = float(args.integer("--max-history", 1, 1 << 20).value_or(32));
    temporal.settledSamples =
        float(args.integer("--settled", 0, 1 << 20).value_or(int(TemporalSettings().settledSamples)));
    std::optional<int> referenceSpp;
    if (args.has("--reference-spp")) referenceSpp = args.integer("--reference-spp", 1, 1 << 20);

    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    Scene scene = request.loadScene();
    const Camera start = request.camera(scene);
    RealtimeRun run(pathName == "orbit" ? orbitPath(start, orbitSpeed, double(frames) / fps)
                                        : readCameraPath(pathName));
    run.frames = frames;
    run.fps = fps;
    if (args.has("--spp")) run.fixedSpp = request.spp(scene);
    run.temporal = temporal;
    run.referenceSpp = referenceSpp;
    run.referenceCache = args.text("--reference-cache");
    if (run.referenceCache && !referenceSpp) throw UsageError("--reference-cache needs --reference-spp K");
    run.sceneKey = request.scenePath().value_or("built-in Cornell box") + ", environment " +
                   args.text("--environment").value_or("the scene's");
    run.settings = request.settings(scene);
    run.display = request.display();
    run.outDir = *out;

    std::unique_ptr<GlContext> context = createOffscreenContext(request.backend());
    std::fprintf(stderr, "renderer: %s\n", context->description().c_str());
    Renderer renderer(scene, ShaderLibrary(request.shaderDir()), layout::bvhOptions(request.bvhThreads()));
    std::vector<FrameRow> rows = renderRealtime(
        renderer, run,
        [&](const FrameRow& r) {
            std::fprintf(stderr, "\rframe %d/%d: %.1f ms, %d spp", r.frame + 1, frames, r.ms(), r.spp);
        },
        [] { return gInterrupted != 0; });
    std::fprintf(stderr, "\n");
    std::printf("%zu frames written to %s (frames.csv)\n", rows.size(), out->c_str());
    return gInterrupted ? 130 : 0;
}

}  // namespace fp
