#pragma once
// What a render is asked to do, independent of the front end that asks.
#include <cstdint>
#include <optional>
#include <string>

namespace fp {

// The estimators, in the order a course would teach them (glsl/integrators/<name>.glsl).
enum class Integrator { Naive, Bsdf, Nee, Bdpt };
constexpr Integrator kAllIntegrators[] = {Integrator::Naive, Integrator::Bsdf, Integrator::Nee,
                                          Integrator::Bdpt};

Integrator parseIntegrator(const std::string& name);  // throws fp::Error listing the choices
const char* integratorName(Integrator integrator);

// Where the random numbers come from (glsl/common/rng.glsl): Owen-scrambled Sobol points, stratified per
// pixel (Burley 2020), or independent uniform numbers, the textbook's plain Monte Carlo.
enum class Sampler { Independent, Sobol };
constexpr Sampler kAllSamplers[] = {Sampler::Sobol, Sampler::Independent};
Sampler parseSampler(const std::string& name);  // throws fp::Error listing the choices
const char* samplerName(Sampler sampler);

// How next-event estimation samples a point on an emitter (glsl/common/lights.glsl): uniformly by area,
// or uniformly in the solid angle the emitter subtends (Arvo 1995) where that is large; auto picks
// solid angle for scenes with an emitter close to a surface it faces (pack/light_strategy.h).
enum class LightSampling { Auto, Area, SolidAngle };
constexpr LightSampling kAllLightSamplings[] = {LightSampling::Auto, LightSampling::Area,
                                                LightSampling::SolidAngle};
LightSampling parseLightSampling(const std::string& name);  // throws fp::Error listing the choices
const char* lightSamplingName(LightSampling sampling);

// How next-event estimation chooses the emitter it samples (glsl/common/lights.glsl): in proportion to
// its power, or by descending the light tree (pack/light_tree.h), which weighs power by distance and
// orientation from the shading point; auto picks the tree for scenes of many emitters
// (pack/light_strategy.h). nee only: the other integrators choose by power.
enum class LightSelection { Auto, Power, Tree };
constexpr LightSelection kAllLightSelections[] = {LightSelection::Auto, LightSelection::Power,
                                                  LightSelection::Tree};
LightSelection parseLightSelection(const std::string& name);  // throws fp::Error listing the choices
const char* lightSelectionName(LightSelection selection);

// How nee finds caustics seen directly (light through smooth glass or off a mirror onto a surface the
// camera sees; glsl/integrators/nee.glsl): by camera paths alone, which reach a small light through the
// glass only by chance, or by light paths traced from the lights toward the caustic casters and joined to
// the camera (a second pass, as LuxCoreRender's hybrid back/forward path tracing does); auto picks light
// for scenes with surfaces of a delta lobe and a light the light paths can start from
// (pack/caustic_casters.h). nee only; unbiased either way.
enum class Caustics { Auto, Path, Light };
constexpr Caustics kAllCaustics[] = {Caustics::Auto, Caustics::Path, Caustics::Light};
Caustics parseCaustics(const std::string& name);  // throws fp::Error listing the choices
const char* causticsName(Caustics caustics);

// What each pixel shows: the rendered radiance, one property of the first hit, or a cost the path
// tracer pays there (glsl/passes/debug_views.glsl).
// Cost: per path, (BVH nodes visited, triangles tested, surfaces shaded) summed over all its rays, in RGB.
enum class View {
    Radiance = 0,
    Depth = 1,
    Normal = 2,
    Albedo = 3,
    Bounces = 4,
    Nodes = 5,
    Triangles = 6,
    Cost = 7
};
// Views that count something, best shown as a heat map.
inline bool isCountView(View v) {
    return v == View::Bounces || v == View::Nodes || v == View::Triangles;
}

constexpr View kAllViews[] = {View::Radiance, View::Depth, View::Normal,    View::Albedo,
                              View::Bounces,  View::Nodes, View::Triangles, View::Cost};
View parseView(const std::string& name);  // throws fp::Error listing the choices
const char* viewName(View view);

// Split view, for teaching: the right half of the image uses another integrator or depth, at the same
// sample count, so that the difference in noise shows at a glance.
// Bounces, as in pbrt: 0 shows only emitters seen directly, 1 adds direct lighting, ... The default of
// every front end (request/render_request.h), the split view and the native reference.
constexpr int kDefaultMaxDepth = 5;
// Seeds are 31-bit so that every front end takes the same range (the study's reference uses seed + 1).
constexpr uint32_t kMaxSeed = 2147483647u;

struct SplitView {
    Integrator integrator = Integrator::Naive;
    int maxDepth = kDefaultMaxDepth;
};

// "auto" for RenderSettings::kAutoSamplesPerPass, else the count.
std::string samplesPerPassName(int samplesPerPass);

// The values of the settings table's rows (settings/setting_table.h), whose defaults are these.
struct RenderSettings {
    int width = 512, height = 512;
    // Samples per pixel to reach, where the front end stops (the renderer renders what it is asked);
    // 0: until stopped.
    int spp = 64;
    int maxDepth = kDefaultMaxDepth;
    uint32_t seed = 0;
    Integrator integrator = Integrator::Nee;
    Sampler sampler = Sampler::Sobol;
    LightSampling lightSampling = LightSampling::Auto;
    LightSelection lightSelection = LightSelection::Auto;
    Caustics caustics = Caustics::Auto;
    View view = View::Radiance;
    // Samples each pixel takes in one draw call of Renderer::render: 0 (the default) chooses the count
    // per pass from the last pass's time (render/pass_pacer.h), 1 to kMaxSamplesPerPass fixes it. At
    // most kMaxSamplesPerPass: llvmpipe stops a shader's loops after a fixed number of iterations in all
    // (measured: 256 samples of the 32x32 Cornell box in one pass left some pixels with 157), which could
    // cut a path short; real GPUs have draw-time watchdogs. The image is the same for every count.
    int samplesPerPass = kAutoSamplesPerPass;
    static constexpr int kAutoSamplesPerPass = 0;
    static constexpr int kMaxSamplesPerPass = 16;
    std::optional<SplitView> split;
    uint32_t sampleOffset = 0;  // the first sample index (to render one range of a larger render)
    // Also accumulate the first-hit guides (normal, depth, albedo) that the denoisers (src/denoise/)
    // need. Off by default: it traces each camera ray once more (about 10% of a Cornell-box path).
    bool guides = false;
    // Each sample's indirect light (paths of two bounces or more) scaled down to a largest channel of at
    // most this (glsl/common/surface.glsl, takeIndirect); 0 clamps nothing. Biased: it removes
    // fireflies by removing energy. nee, bsdf and naive only.
    float clampIndirect = 0.0f;
};

}  // namespace fp
