#include "app/render_stats.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/text.h"
#include "image/file_io.h"
#include "settings/settings_json.h"

namespace fp {

namespace {

// a / b, or 0 when b is not positive (a render too short for the clock, a scene without triangles).
double per(double a, double b) {
    return b > 0.0 ? a / b : 0.0;
}

}  // namespace

RenderStats collectRenderStats(const Renderer& renderer, const Accumulation& acc,
                               const std::string& glRenderer, const std::string& scene,
                               const std::string& output, const RenderTimes& times) {
    RenderStats s;
    s.renderer = glRenderer;
    s.scene = scene;
    s.output = output;
    s.sceneStats = renderer.stats();
    s.settings = renderer.settings();
    s.imageBytes = renderer.imageBytes();
    s.lightImage = !acc.splatSum.empty();
    s.spp = times.spp;
    s.passes = renderer.passes();
    s.paths = uint64_t(s.settings.width) * uint64_t(s.settings.height) * uint64_t(std::max(times.spp, 0));
    s.rays = uint64_t(std::llround(acc.raysTraced()));
    s.droppedSamples = acc.droppedSamples();
    s.firstFrameSeconds = times.firstFrameSeconds;
    s.firstFrame = times.firstFrame;
    s.seconds = times.seconds;
    s.cpuSeconds = times.cpuSeconds;
    return s;
}

std::string formatRenderStats(const RenderStats& stats) {
    const SceneStats& s = stats.sceneStats;
    const RenderSettings& settings = stats.settings;
    const double paths = double(stats.paths), rays = double(stats.rays);
    std::string text;
    text += formatText("renderer         %s\n", stats.renderer.c_str());
    text += formatText("scene            %s\n", stats.scene.c_str());
    text += formatText("triangles        %u (%u emissive)\n", s.triangles, s.emitters);
    if (s.instances > 0)
        text += formatText("instances        %u: %u triangles stored, %u drawn\n", s.instances,
                           s.storedTriangles, s.triangles);
    if (s.punctualLights > 0) text += formatText("punctual lights  %u\n", s.punctualLights);
    text += formatText(
        "bvh              %u nodes, %u leaves, depth %u, leaf size %u..%u (mean %.2f), SAH cost %.2f, "
        "traversal stack %u\n",
        s.bvh.nodeCount, s.bvh.leafCount, s.bvh.maxDepth, s.bvh.minLeafSize, s.bvh.maxLeafSize,
        s.bvh.meanLeafSize, s.bvh.sahCost, s.stackSize);
    text +=
        formatText("bvh build        %.3f s, %.3f CPU-s, threads %d (%.3g triangles/s)\n", s.bvhBuildSeconds,
                   s.bvhBuildCpuSeconds, s.bvhBuildThreads, per(s.storedTriangles, s.bvhBuildSeconds));
    text += formatText(
        "gpu memory       %zu bytes (%.1f per triangle; positions + BVH %.1f per triangle; textures %zu "
        "bytes)\n",
        s.gpuBytes, per(double(s.gpuBytes), s.triangles), per(double(s.gpuGeometryBytes), s.triangles),
        s.gpuTextureBytes);
    text += formatText("scene reads      %s\n", sceneReadsName(s.sceneReads));
    text += formatText("image buffers    %zu bytes (%.0f per pixel: accumulation%s)\n", stats.imageBytes,
                       per(double(stats.imageBytes), double(settings.width) * settings.height),
                       stats.lightImage ? " and the light image" : "");
    text +=
        formatText("first frame      %.3f s after start (load, build, upload, shader compile, first pass)\n",
                   stats.firstFrameSeconds);
    const FirstFrameStages& f = stats.firstFrame;
    text += formatText(
        "  of which       load %.3f, context %.3f, bvh %.3f, pack + upload %.3f, compile %.3f, first pass "
        "%.3f s; %.3f CPU-s\n",
        f.loadSeconds, f.contextSeconds, f.bvhSeconds, f.packAndUploadSeconds, f.compileSeconds,
        f.firstPassSeconds, f.cpuSeconds);
    text +=
        formatText("samples          %d per pixel in %d passes, %.0f paths, %.0f rays (%.2f rays per path)\n",
                   stats.spp, stats.passes, paths, rays, per(rays, paths));
    text += formatText("throughput       %.3g paths/s, %.3g rays/s, %.3g paths per CPU-second\n",
                       per(paths, stats.seconds), per(rays, stats.seconds), per(paths, stats.cpuSeconds));
    text += formatText("dropped samples  %llu (NaN or Inf, replaced by 0)\n",
                       (unsigned long long)stats.droppedSamples);
    return text;
}

nlohmann::json renderStatsJson(const RenderStats& stats) {
    const SceneStats& s = stats.sceneStats;
    const RenderSettings& settings = stats.settings;
    const double paths = double(stats.paths), rays = double(stats.rays);
    nlohmann::json bvh = {
        {"nodes", s.bvh.nodeCount},
        {"leaves", s.bvh.leafCount},
        {"depth", s.bvh.maxDepth},
        {"leaf_size", {{"min", s.bvh.minLeafSize}, {"max", s.bvh.maxLeafSize}, {"mean", s.bvh.meanLeafSize}}},
        {"sah_cost", s.bvh.sahCost},
        {"build_seconds", s.bvhBuildSeconds},
        {"build_cpu_seconds", s.bvhBuildCpuSeconds},
        {"build_threads", s.bvhBuildThreads},
    };
    nlohmann::json memory = {
        {"gpu_bytes", s.gpuBytes},
        {"gpu_geometry_bytes", s.gpuGeometryBytes},
        {"gpu_texture_bytes", s.gpuTextureBytes},
        {"image_bytes", stats.imageBytes},
    };
    nlohmann::json throughput = {
        {"paths_per_second", per(paths, stats.seconds)},
        {"rays_per_second", per(rays, stats.seconds)},
        {"paths_per_cpu_second", per(paths, stats.cpuSeconds)},
    };
    nlohmann::json renderSettings = settingsJson(settings);
    return {
        {"renderer", stats.renderer},
        {"scene", stats.scene},
        {"output", stats.output},
        {"triangles", s.triangles},
        {"stored_triangles", s.storedTriangles},
        {"instances", s.instances},
        {"emitters", s.emitters},
        {"punctual_lights", s.punctualLights},
        {"bvh", bvh},
        {"memory", memory},
        {"scene_reads", sceneReadsName(s.sceneReads)},
        {"first_frame_seconds", stats.firstFrameSeconds},
        {"first_frame",
         {{"load_seconds", stats.firstFrame.loadSeconds},
          {"context_seconds", stats.firstFrame.contextSeconds},
          {"bvh_seconds", stats.firstFrame.bvhSeconds},
          {"pack_and_upload_seconds", stats.firstFrame.packAndUploadSeconds},
          {"compile_seconds", stats.firstFrame.compileSeconds},
          {"first_pass_seconds", stats.firstFrame.firstPassSeconds},
          {"cpu_seconds", stats.firstFrame.cpuSeconds}}},
        {"spp", stats.spp},
        {"passes", stats.passes},
        {"paths", stats.paths},
        {"rays", stats.rays},
        {"rays_per_path", per(rays, paths)},
        {"seconds", stats.seconds},
        {"cpu_seconds", stats.cpuSeconds},
        {"throughput", throughput},
        {"dropped_samples", stats.droppedSamples},
        {"settings", renderSettings},
    };
}

void writeRenderStatsJson(const std::string& path, const RenderStats& stats) {
    const std::string text = renderStatsJson(stats).dump(2) + "\n";
    writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

}  // namespace fp
