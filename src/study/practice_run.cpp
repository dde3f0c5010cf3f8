#include "study/practice_run.h"

#include <filesystem>

#include "core/error.h"
#include "realtime/realtime_run.h"
#include "realtime/reference_cache.h"
#include "realtime/temporal_pipeline.h"

namespace fp::study {

namespace {

PracticeRun runOnce(Renderer& renderer, const RealtimeRun& base, const std::string& camera,
                    PracticeMethod method, int spp, const std::string& dir) {
    RealtimeRun run = base;
    run.fixedSpp = spp;
    if (method == PracticeMethod::BruteForce) {
        run.temporal.reuse = false;  // `fragpath realtime --temporal off --filter none`
        run.temporal.filter = Denoiser::None;
    }
    run.outDir = dir;
    std::vector<PracticeFrame> frames;
    for (const FrameRow& row : renderRealtime(renderer, run)) {
        if (!row.flip) throw Error("practice run: frame " + std::to_string(row.frame) + " has no FLIP");
        frames.push_back({row.ms(), *row.flip, row.meanHistoryFrames, row.flicker});
    }
    return summarisePractice(camera, method, spp, frames);
}

// A still camera sees the same view every frame, and renderRealtime renders each frame's reference
// with the same samples, so one reference stands for all: render frame 0's (a 1-frame run into the
// directory the first full run overwrites) and store it for the others.
void shareStillReference(Renderer& renderer, const RealtimeRun& base, const std::string& dir) {
    RealtimeRun first = base;
    first.frames = 1;
    first.fixedSpp = 1;
    first.outDir = dir;
    renderRealtime(renderer, first);
    ReferenceCache cache(*base.referenceCache,
                         ReferenceCache::describe(base.sceneKey, base.settings, *base.referenceSpp));
    const Camera camera = base.path.at(base.path.startTime());
    std::optional<Image> reference = cache.find(0, camera);
    if (!reference) throw Error("practice run: the still camera's reference was not stored");
    for (int f = 1; f < base.frames; ++f) {
        const Camera frameCamera = base.path.at(base.path.startTime() + double(f) / base.fps);
        cache.store(f, frameCamera, *reference);
    }
}

}  // namespace

PracticeInput measurePractice(Renderer& renderer, const PracticeOptions& o) {
    if (o.frames < 1) throw Error("practice: needs at least 1 frame");
    if (o.referenceSpp < 1) throw Error("practice: the reference needs at least 1 sample per pixel");
    PracticeInput input;
    input.width = o.settings.width;
    input.height = o.settings.height;
    input.frames = o.frames;
    input.referenceSpp = o.referenceSpp;
    input.fps = o.fps;
    input.orbitDegreesPerSecond = o.orbitDegreesPerSecond;
    input.integrator = integratorName(o.settings.integrator);
    input.scene = o.sceneName;
    input.settledSamples = TemporalSettings{}.settledSamples;  // the runs keep the pipeline's defaults
    input.flipThreshold = o.flipThreshold;
    input.outDir = o.outDir;
    auto say = [&](const std::string& line) {
        if (o.progress) o.progress(line);
    };

    for (const std::string camera : {"still", "moving"}) {
        const bool still = camera == "still";
        const std::filesystem::path dir = std::filesystem::path(o.outDir) / camera;
        const std::string references = (dir / "references").string();
        std::filesystem::remove_all(references);
        RealtimeRun base(
            orbitPath(o.camera, still ? 0.0 : o.orbitDegreesPerSecond, double(o.frames) / o.fps));
        base.frames = o.frames;
        base.fps = o.fps;
        base.referenceSpp = o.referenceSpp;
        base.referenceCache = references;
        base.sceneKey = o.sceneKey;
        base.settings = o.settings;
        base.display = o.display;

        const std::string bruteOne = (dir / "brute_force_1spp").string();
        say("practice, " + camera + " camera: references (" + std::to_string(o.referenceSpp) +
            " spp) and brute force at 1 spp");
        if (still) shareStillReference(renderer, base, bruteOne);
        PracticeRun one = runOnce(renderer, base, camera, PracticeMethod::BruteForce, 1, bruteOne);
        say("practice, " + camera + " camera: the pipeline at 1 spp");
        PracticeRun pipeline =
            runOnce(renderer, base, camera, PracticeMethod::Pipeline, 1, (dir / "pipeline_1spp").string());
        const int equalSpp = equalTimeSpp(pipeline.msPerFrame, one.msPerFrame);
        say("practice, " + camera + " camera: brute force at " + std::to_string(equalSpp) +
            " spp (equal time)");
        PracticeRun equal =
            runOnce(renderer, base, camera, PracticeMethod::BruteForce, equalSpp,
                    (dir / ("brute_force_equal_time_" + std::to_string(equalSpp) + "spp")).string());
        equal.equalTime = true;
        input.runs.push_back(one);
        input.runs.push_back(pipeline);
        input.runs.push_back(equal);
        if (still) continue;
        // What the pipeline needs per frame to get under the FLIP threshold while the camera moves.
        for (int spp = 2; pipeline.judgedFlip() > o.flipThreshold && spp <= kPracticeMaxSpp; spp *= 2) {
            say("practice, moving camera: the pipeline at " + std::to_string(spp) + " spp");
            pipeline = runOnce(renderer, base, camera, PracticeMethod::Pipeline, spp,
                               (dir / ("pipeline_" + std::to_string(spp) + "spp")).string());
            input.runs.push_back(pipeline);
        }
    }
    return input;
}

}  // namespace fp::study
