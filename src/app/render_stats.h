#pragma once
// The statistics of `fragpath render`: what --stats prints and what --json FILE writes for scripts,
// both made from one RenderStats that the command fills after rendering.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "render/accumulation.h"
#include "render/renderer.h"

namespace fp {

// Where the first frame's time went, stage by stage in the order the command runs them (as `bench`
// times them): what the figure of a slow start is made of.
struct FirstFrameStages {
    double loadSeconds = 0.0;           // reading and parsing the scene file, textures decoded
    double contextSeconds = 0.0;        // the OpenGL context
    double bvhSeconds = 0.0;            // SceneStats::bvhBuildSeconds
    double packAndUploadSeconds = 0.0;  // the renderer's construction less the BVH build
    double compileSeconds = 0.0;        // configure(): GLSL compile and link
    double firstPassSeconds = 0.0;      // the first pass, with llvmpipe's JIT at the first draw
    double cpuSeconds = 0.0;            // process CPU time (every thread) from the start to the first frame
};

struct RenderStats {
    std::string renderer;  // the OpenGL renderer (GlContext::description)
    std::string scene;     // Scene::source
    std::string output;    // the -o file
    SceneStats sceneStats;
    RenderSettings settings;
    size_t imageBytes = 0;    // Renderer::imageBytes
    bool lightImage = false;  // a light-tracing pass (bdpt, nee's caustics) filled a light image
    // This run's samples per pixel (a resumed render: those rendered now), and its paths (one per
    // pixel and sample) and rays (camera, bounce and shadow rays of those paths).
    int spp = 0;
    int passes = 0;  // the draw calls that took them (RenderSettings::samplesPerPass)
    uint64_t paths = 0, rays = 0, droppedSamples = 0;
    double firstFrameSeconds = 0.0;  // from the start of the command to the end of the first pass
    FirstFrameStages firstFrame;
    double seconds = 0.0, cpuSeconds = 0.0;  // of the passes: wall clock and process CPU time
};

// What the command measured besides the renderer: times, and the samples per pixel of this run.
struct RenderTimes {
    int spp = 0;
    double firstFrameSeconds = 0.0, seconds = 0.0, cpuSeconds = 0.0;
    FirstFrameStages firstFrame;
};

RenderStats collectRenderStats(const Renderer& renderer, const Accumulation& acc,
                               const std::string& glRenderer, const std::string& scene,
                               const std::string& output, const RenderTimes& times);

// The text --stats prints: one "name   value" line per subject.
std::string formatRenderStats(const RenderStats& stats);
// The same figures for scripts, as a JSON object (keys in snake_case; rates are 0 when their time is 0):
// {"renderer", "scene", "output", "triangles", "emitters", "bvh": {"nodes", "leaves", "depth",
// "leaf_size": {"min", "max", "mean"}, "sah_cost", "build_seconds", "build_cpu_seconds",
// "build_threads"}, "memory": {"gpu_bytes", "gpu_geometry_bytes", "gpu_texture_bytes", "image_bytes"},
// "scene_reads", "first_frame_seconds", "first_frame": {"load_seconds", "context_seconds", "bvh_seconds",
// "pack_and_upload_seconds", "compile_seconds", "first_pass_seconds", "cpu_seconds"}, "spp", "passes",
// "paths", "rays", "rays_per_path", "seconds", "cpu_seconds", "throughput": {"paths_per_second",
// "rays_per_second", "paths_per_cpu_second"}, "dropped_samples", "settings": {one key a row of the
// settings table, settings/settings_json.h}}.
nlohmann::json renderStatsJson(const RenderStats& stats);

// Writes renderStatsJson (indented, one trailing newline), atomically.
void writeRenderStatsJson(const std::string& path, const RenderStats& stats);

}  // namespace fp
