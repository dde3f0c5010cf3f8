#include "realtime/realtime_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/clock.h"
#include "core/error.h"
#include "image/error_metrics.h"
#include "image/file_io.h"
#include "image/flip.h"
#include "image/image_grid.h"
#include "image/image_stats.h"
#include "image/png.h"
#include "realtime/frame_budget.h"
#include "realtime/reference_cache.h"

namespace fp {

namespace {

const char* const kCsvHeader =
    "frame,ms,spp,trace_ms,temporal_ms,filter_ms,mean_history_frames,rmse,rel_mse,ssim,flip,flicker";

std::string optionalField(const std::optional<double>& value) {
    if (!value) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", *value);
    return text;
}

std::string csvRow(const FrameRow& r) {
    char text[160];
    std::snprintf(text, sizeof text, "%d,%.3f,%d,%.3f,%.3f,%.3f,%.3f,", r.frame, r.ms(), r.spp, r.traceMs,
                  r.temporalMs, r.filterMs, r.meanHistoryFrames);
    return text + optionalField(r.rmse) + "," + optionalField(r.relMse) + "," + optionalField(r.ssim) + "," +
           optionalField(r.flip) + "," + optionalField(r.flicker);
}

// Sample indices of the references, far from the frames' (which count up from 0), so that a frame and
// its reference share no sample.
constexpr uint32_t kReferenceOffset = 1u << 28;

// Five frames evenly spread over the run (first and last included), left to right, above their
// references when there are any, 2-pixel grey gaps between tiles, labelled (image/image_grid.h) with
// their frame numbers and "frames" / "reference": the run at a glance.
constexpr int kStripFrames = 5;
bool inStrip(int frame, int frames) {
    for (int i = 0; i < kStripFrames; ++i)
        if (frame == (frames - 1) * i / (kStripFrames - 1)) return true;
    return false;
}

Image assembleStrip(const std::vector<Image>& top, const std::vector<Image>& bottom,
                    const std::vector<int>& frameNumbers, const DisplaySettings& display) {
    GridLabels labels;
    std::vector<std::vector<const Image*>> tiles(bottom.empty() ? 1 : 2);
    for (size_t i = 0; i < top.size(); ++i) {
        tiles[0].push_back(&top[i]);
        if (!bottom.empty()) tiles[1].push_back(&bottom[i]);
        labels.columns.push_back("frame " + std::to_string(frameNumbers[i]));
    }
    labels.rows = {"frames"};
    if (!bottom.empty()) labels.rows.push_back("reference");
    // White text under the run's exposure and any tone curve: Reinhard's x / (1 + x) encodes to 255 from
    // about x = 500, ACES and the clamp from 1.
    labels.colour = glm::vec3(1e3f * std::exp2(-display.exposure));
    return assembleGrid(tiles, PixelRect{0, 0, top[0].width, top[0].height}, labels);
}

}  // namespace

double flicker(const std::vector<float>& luma, const std::vector<float>& previousLuma,
               const std::vector<float>* reference, const std::vector<float>* previousReference) {
    if (luma.size() != previousLuma.size() || luma.empty()) throw Error("flicker: frames of different sizes");
    double sum = 0.0;
    for (size_t i = 0; i < luma.size(); ++i) {
        double e = luma[i], before = previousLuma[i];
        if (reference && previousReference) {
            e -= (*reference)[i];
            before -= (*previousReference)[i];
        }
        sum += std::abs(e - before);
    }
    return sum / double(luma.size());
}

std::vector<FrameRow> renderRealtime(Renderer& renderer, const RealtimeRun& run,
                                     const std::function<void(const FrameRow&)>& onFrame,
                                     const std::function<bool()>& stop) {
    std::filesystem::create_directories(run.outDir);
    const std::string csvPath = run.outDir + "/frames.csv";
    std::string csv = std::string(kCsvHeader) + "\n";
    TemporalPipeline pipeline(renderer.shaders());
    std::vector<FrameRow> rows;
    std::vector<float> previousLuma, previousReference;
    std::vector<Image> stripFrames, stripReferences;
    std::optional<ReferenceCache> cache;
    if (run.referenceSpp && run.referenceCache)
        cache.emplace(*run.referenceCache,
                      ReferenceCache::describe(run.sceneKey, run.settings, *run.referenceSpp));
    std::vector<int> stripFrameNumbers;
    int spp = run.fixedSpp.value_or(1);
    uint32_t sampleOffset = 0;
    for (int f = 0; f < run.frames && !(stop && stop()); ++f) {
        const Camera camera = run.path.at(run.path.startTime() + double(f) / run.fps);
        validateCamera(camera, "the camera path at frame " + std::to_string(f));
        RenderSettings s = run.settings;
        s.guides = true;
        s.samplesPerPass = std::min(spp, RenderSettings::kMaxSamplesPerPass);
        s.sampleOffset = sampleOffset;
        sampleOffset += uint32_t(spp);
        FrameRow row;
        row.frame = f;
        row.spp = spp;
        auto start = SteadyClock::now();
        renderer.configure(s, camera);
        renderer.render(spp);
        glFinish();
        row.traceMs = 1e3 * secondsSince(start);
        pipeline.run(renderer, camera, run.temporal);
        row.temporalMs = 1e3 * pipeline.timings().temporalSeconds;
        row.filterMs = 1e3 * pipeline.timings().filterSeconds;
        std::vector<float> history = pipeline.historySamples();
        double samples = 0.0;
        for (float n : history) samples += n;
        row.meanHistoryFrames = samples / double(history.size()) / double(spp);
        Image image = pipeline.result();
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%04d.png", f);
        writePng(run.outDir + name, image, run.display);

        std::vector<float> luma = displayLuma(image), referenceLuma;
        if (inStrip(f, run.frames)) {
            stripFrames.push_back(image);
            stripFrameNumbers.push_back(f);
        }
        if (run.referenceSpp) {
            std::optional<Image> reference = cache ? cache->find(f, camera) : std::nullopt;
            if (!reference) {
                RenderSettings r = run.settings;
                r.guides = true;  // as the frames: changing it would recompile the shaders every frame
                r.samplesPerPass = std::min(*run.referenceSpp, RenderSettings::kMaxSamplesPerPass);
                r.sampleOffset = kReferenceOffset;
                renderer.configure(r, camera);
                renderer.render(*run.referenceSpp);
                reference = renderer.readback().mean();
                if (cache) cache->store(f, camera, *reference);
            }
            row.rmse = rmse(image, *reference);
            row.relMse = relativeMse(image, *reference);
            row.ssim = ssim(image, *reference);
            row.flip = hdrFlip(image, *reference, kDefaultPixelsPerDegree).mean;
            referenceLuma = displayLuma(*reference);
            if (inStrip(f, run.frames)) stripReferences.push_back(*reference);
        }
        if (f > 0)
            row.flicker = flicker(luma, previousLuma, run.referenceSpp ? &referenceLuma : nullptr,
                                  run.referenceSpp ? &previousReference : nullptr);
        previousLuma = std::move(luma);
        previousReference = std::move(referenceLuma);
        if (!run.fixedSpp)
            spp = adaptSamplesPerFrame(row.spp, row.traceMs, run.fps, row.temporalMs + row.filterMs);
        rows.push_back(row);
        csv += csvRow(row) + "\n";
        writeFileAtomically(csvPath, std::vector<std::uint8_t>(csv.begin(), csv.end()));
        if (onFrame) onFrame(row);
    }
    if (!stripFrames.empty())
        writePng(run.outDir + "/strip.png",
                 assembleStrip(
                     stripFrames,
                     stripReferences.size() == stripFrames.size() ? stripReferences : std::vector<Image>{},
                     stripFrameNumbers, run.display),
                 run.display);
    return rows;
}

}  // namespace fp
