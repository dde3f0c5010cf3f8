#pragma once
// The one renderer every front end drives: scene -> BVH -> GPU textures -> trace passes -> accumulation.
// Needs a current GL context (gl/context.h); the front ends never call GL themselves.
#include <functional>
#include <memory>

#include "bvh/bvh.h"
#include "gl/program.h"
#include "gpu/pack.h"
#include "gpu/scene_textures.h"
#include "render/accumulation.h"
#include "render/render_targets.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace fp {

struct SceneStats {
    uint32_t triangles = 0, emitters = 0;
    BvhStats bvh;
    double bvhBuildSeconds = 0.0, uploadSeconds = 0.0;
    size_t gpuBytes = 0, gpuGeometryBytes = 0;  // all buffers; positions + BVH only
    uint32_t stackSize = 0;                     // traversal stack entries the shader was compiled with
};

class Renderer {
  public:
    Renderer(const Scene& scene, ShaderLibrary shaders = ShaderLibrary(), const BvhBuildOptions& bvh = {});
    ~Renderer();

    // Sets what to render; restarts accumulation, recompiling shaders only when the integrator changed.
    void configure(const RenderSettings& settings, const Camera& camera);
    // Adds `samples` samples per pixel; `progress(done)` is called after every pass and may return
    // false to stop early (an interrupted render keeps what it has).
    void render(int samples, const std::function<bool(int done)>& progress = nullptr);
    // Recompiles the shaders from the library (for hot reload); throws fp::Error and keeps the old program.
    void reloadShaders();

    int samples() const { return samples_; }
    Accumulation readback() const;
    const SceneStats& stats() const { return stats_; }
    const RenderSettings& settings() const { return settings_; }

  private:
    void compile();
    ShaderLibrary shaders_;
    SceneStats stats_;
    float rayOffset_ = 0.0f;
    uint32_t lightCount_ = 0;
    std::unique_ptr<SceneTextures> textures_;
    std::unique_ptr<RenderTargets> targets_;
    std::unique_ptr<Program> program_;
    GLuint vertexArray_ = 0;
    RenderSettings settings_;
    Camera camera_;
    bool configured_ = false;
    int samples_ = 0;
};

}  // namespace fp
