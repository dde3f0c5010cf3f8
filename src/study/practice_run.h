#pragma once
// The measurement behind the study's "Practice" section (study/practice.h): the real-time pipeline of
// `fragpath realtime` (renderRealtime with its default temporal settings, 1 spp per frame) against
// brute force (--temporal off --filter none) at 1 spp and at equal time, on a still and an orbiting
// camera, every run of a camera judged against the same references (realtime/reference_cache.h).
#include <functional>
#include <string>

#include "realtime/camera_path.h"
#include "realtime/frame_budget.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "settings/render_settings.h"
#include "study/practice.h"

namespace fp::study {

struct PracticeOptions {
    RenderSettings settings;  // size, integrator, depth, seed, sampler
    DisplaySettings display;
    Camera camera;          // the still camera, and where the orbit starts
    std::string sceneName;  // as the report names it (PracticeInput::scene)
    std::string sceneKey;   // names the scene in the references' key
    int frames = 20;
    int referenceSpp = 128;  // the study's defaults (--practice-frames, --practice-reference-spp)
    double fps = kDefaultFps,
           orbitDegreesPerSecond = kDefaultOrbitDegreesPerSecond;  // `fragpath realtime`'s defaults
    double flipThreshold = kDefaultFlipThreshold;                  // the study's --flip-threshold
    // Each run writes DIR/<camera>/<run>/ (frames, frames.csv, strip.png); the references go to
    // DIR/<camera>/references/, emptied first so that a study with other settings never meets them.
    std::string outDir;
    std::function<void(const std::string&)> progress;
};

// Runs, per camera: brute force at 1 spp, the pipeline at 1 spp, brute force at equalTimeSpp of the
// two; then, on the moving camera, the pipeline at 2, 4, ... kPracticeMaxSpp spp per frame until its
// judged FLIP is at most the threshold. Throws fp::Error for frames or reference spp below 1.
PracticeInput measurePractice(Renderer& renderer, const PracticeOptions& options);

}  // namespace fp::study
