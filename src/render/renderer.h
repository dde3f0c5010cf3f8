#pragma once
// The one renderer every front end drives: scene -> BVH -> GPU textures -> trace passes -> accumulation.
// Needs a current GL context (gl/context.h); the front ends never call GL themselves.
#include <functional>
#include <memory>

#include "bvh/bvh.h"
#include "gl/program.h"
#include "gpu/environment.h"
#include "gpu/scene_textures.h"
#include "pack/layout.h"
#include "pack/pack.h"
#include "render/accumulation.h"
#include "render/light_splat.h"
#include "render/pass_pacer.h"
#include "render/render_targets.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace fp {

struct SceneStats {
    uint32_t triangles = 0, emitters = 0;  // triangles drawn: the world's and every instance's
    uint32_t storedTriangles = 0;          // in the GPU buffers: each instanced mesh's once
    uint32_t instances = 0;
    uint32_t punctualLights = 0;  // point, spot and directional lights that can be sampled (not black)
    BvhStats bvh;
    double bvhBuildSeconds = 0.0, uploadSeconds = 0.0;
    double bvhBuildCpuSeconds = 0.0;  // process CPU time of the build, all its threads together
    int bvhBuildThreads = 0;
    size_t gpuBytes = 0, gpuGeometryBytes = 0;  // all buffers; positions + BVH only
    size_t gpuTextureBytes = 0;                 // of gpuBytes: texture coordinates, texels and tangents
    size_t gpuPinnedBytes = 0;  // of gpuBytes: read in place, not copied (SceneTextures::pinnedBytes)
    uint32_t stackSize = 0;     // traversal stack entries the shader was compiled with
    SceneReads sceneReads = SceneReads::TexelFetch;  // how the trace shaders read the scene buffers
};

// Whether a renderer finds the scene's caustic casters when it is built (pack/caustic_casters.h: a pass
// over the triangles and a read of every caster candidate's roughness map). Only nee's light pass for
// caustics aims at them, so a front end whose settings are known beforehand skips the search when they
// cannot use it (usesCausticCasters); configure() then refuses settings that would.
enum class CasterSearch { Run, Skip };

// Whether rendering with `settings` may need the caustic casters: nee (either half of a split) with the
// radiance view, its caustics not left to camera paths (--caustics path) nor clamped.
bool usesCausticCasters(const RenderSettings& settings);

class Renderer {
  public:
    // `reads` is resolved for the current context (resolveSceneReads, gpu/scene_textures.h); the choice
    // is in stats().sceneReads.
    Renderer(const Scene& scene, ShaderLibrary shaders = ShaderLibrary(),
             const BvhBuildOptions& bvh = layout::bvhOptions(), SceneReads reads = SceneReads::Auto,
             CasterSearch casters = CasterSearch::Run);
    ~Renderer();

    // Sets what to render; restarts accumulation, recompiling shaders only when the integrator, view, guides
    // or split changed. Throws fp::Error for settings that cannot be rendered. Warns when the scene has
    // punctual lights and an integrator that cannot see them (naive, bsdf) is chosen.
    void configure(const RenderSettings& settings, const Camera& camera);
    // Adds `samples` samples per pixel over the whole image; `progress(done)` is called after every
    // pass and may return false to stop early (an interrupted render keeps what it has). With bdpt each
    // pass also traces the light paths of its samples (one per pixel and sample) into the light image.
    void render(int samples, const std::function<bool(int done)>& progress = nullptr);
    // Adds one sample to the next tile of the image (tiles of tileSize x tileSize pixels, bottom row
    // first), so that an interactive front end can bound the work per frame. Returns true when that
    // completed a sample over the whole image. With bdpt the tile also traces its share of light paths
    // (one per pixel of the tile), which splat anywhere in the image.
    bool renderTile(int tileSize);
    // Continues a saved render: after configure(), takes `samples` samples of per-pixel mean `mean`
    // as already done (their indices must be the settings' sampleOffset onwards). A bdpt mean already
    // holds its light image (divided by its samples), so it counts as that many light paths per pixel.
    void restore(const Image& mean, int samples);
    // Recompiles the shaders from the library (hot reload) and restarts accumulation. Throws fp::Error
    // with the compiler's message, keeping the previous programs.
    void reloadShaders();

    // Samples completed over the whole image (tiles of an unfinished pass not counted).
    int samples() const { return samples_; }
    // Passes render() drew since configure() (their sample counts: RenderSettings::samplesPerPass).
    int passes() const { return passes_; }
    Accumulation readback() const;
    // The accumulation's textures, for a display pass.
    AccumulationTextures textures() const;
    // Any attachment of the accumulation (src/render/render_targets.h), for the denoisers. Only valid
    // after configure().
    GLuint accumulationTexture(Attachment a) const { return targets_->texture(a); }
    const SceneStats& stats() const { return stats_; }
    // Where its shaders come from (built in, or a directory): the denoisers read theirs from there too.
    const ShaderLibrary& shaders() const { return shaders_; }
    // GPU memory of the image buffers the current settings use: the accumulation, and bdpt's light
    // image when the integrator needs it. Scene data is in stats().gpuBytes.
    size_t imageBytes() const;
    const RenderSettings& settings() const { return settings_; }

  private:
    std::unique_ptr<Program> compile(Integrator integrator, const char* fragmentShader) const;
    void compilePrograms(const RenderSettings& settings);
    bool causticsByLight(Integrator integrator, const RenderSettings& settings) const;
    void updateLightSplat(bool rebuild);
    void setTraceUniforms(Program& program, int maxDepth);
    void draw(Program& program, int maxDepth, const PixelRegion& region, int samples);
    // One pass of `samples` samples per pixel over `area` (the image or a tile): the camera pass, then
    // for bdpt the light paths launched from `area`, for each half of a split view.
    void drawPass(const PixelRegion& area, int samples);
    void resetLightImage(int restoredSamples);
    double lightPathsPerPixel() const;

    ShaderLibrary shaders_;
    SceneStats stats_;
    glm::vec3 environmentColor_{0.0f};
    float environmentRotation_ = 0.0f;
    uint32_t materialTypes_ = 0;   // bit mask of the MaterialTypes in the scene
    bool absorbingGlass_ = false;  // some Dielectric absorbs (Material::absorption): MATERIAL_VOLUME
    bool clearcoat_ = false;       // some metallic-roughness material has a clearcoat: MATERIAL_CLEARCOAT
    bool sheen_ = false;           // some metallic-roughness material has a sheen: MATERIAL_SHEEN
    uint32_t lightCount_ = 0;      // entries of the light-selection cdf (pack/layout.h)
    uint32_t lightTreeFirst_ = 0, lightTreeDepth_ = 0;  // the light tree (pack/light_tree.h); 0: none
    uint32_t punctualCount_ = 0;      // of them punctual lights: compile them in (PUNCTUAL_LIGHTS)
    uint32_t instanceNodeStart_ = 0;  // two-level BVH (INSTANCE_NODES_START); 0: one level
    bool closeEmitters_ = false;      // LightSampling::Auto samples by solid angle (pack/light_strategy.h)
    std::vector<glm::vec4>
        causticCasters_;            // spheres nee's caustic light paths aim at (pack/caustic_casters.h)
    bool castersSearched_ = false;  // CasterSearch::Run: causticCasters_ holds them
    bool surfaceTextures_ = false;  // some material has a texture: compile the lookups in
    int surfaceMaps_ = 0;           // which kinds of map (layout::MapBit): SURFACE_MAPS
    bool surfaceOpacity_ = false;   // some material has alpha or is single-sided: SURFACE_OPACITY
    int texcoordSlots_ = 1;         // TEXCOORD_SLOTS (pack/layout.h, texcoords)
    bool textureSampling_ = false;  // some texture clamps, mirrors or is nearest: TEXTURE_SAMPLING
    bool vertexColors_ = false;     // some triangle has vertex colours: VERTEX_COLORS
    std::unique_ptr<SceneTextures> textures_;
    std::unique_ptr<EnvironmentTextures> environmentTextures_;  // only for an environment map
    std::unique_ptr<RenderTargets> targets_;
    std::unique_ptr<Program> program_, splitProgram_;
    // bdpt's light tracing, or nee's for caustics (causticsByLight), else null
    std::unique_ptr<Program> lightProgram_, splitLightProgram_;
    std::unique_ptr<LightSplat> lightSplat_;  // when either is set
    int restoredLightPaths_ = 0;              // per pixel, in a resumed mean
    uint64_t launchedLightPaths_ = 0;         // light paths traced into the light image (over all pixels)
    GLuint vertexArray_ = 0;
    RenderSettings settings_;
    Camera camera_;
    int samples_ = 0;
    int passes_ = 0;                                          // render()'s passes since configure()
    PassPacer pacer_{0, RenderSettings::kMaxSamplesPerPass};  // render()'s samples per pass
    int nextTile_ = 0;
};

}  // namespace fp
