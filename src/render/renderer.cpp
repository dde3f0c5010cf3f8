#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"
#include "gpu/layout_defines.h"
#include "pack/caustic_casters.h"
#include "pack/layout.h"
#include "pack/light_strategy.h"
#include "scene/spectrum.h"
#include "settings/integrators.h"
#include "settings/setting_table.h"

namespace fp {

namespace {

constexpr int kSumUnit = layout::kFirstFreeUnit;  // then the other attachments, in order
constexpr int kSpareUnit = kSumUnit + RenderTargets::kAttachments;
// nee's caustic light paths: one pixel in this many launches one per sample (glsl/passes/light_launch.glsl).
// On the glass Cornell box (128x128, 64 spp) more paths did not lower the image's variance (one in 1, 4,
// 16 and 64: 3.64e-4, 3.63e-4, 3.65e-4, 3.73e-4) but cost 60 %, 30 % and 5 % more CPU time at 1, 4 and 16.
constexpr int kCausticLaunchStride = 16;
// The light pass's caustic paths: up to this many smooth vertices x1 .. x_j before the delta ones (1: the
// caustic seen directly; 2: a wall lit by the caustic on the floor; 3: by way of another wall). Its light
// paths through a glass ball then have 2 + 1 + 3 vertices: LightSplat::kLightVertices.
constexpr int kCausticSmoothBounces = 3;
static_assert(kCausticSmoothBounces + 3 <= LightSplat::kLightVertices);

}  // namespace

bool usesCausticCasters(const RenderSettings& settings) {
    if (settings.view != View::Radiance || settings.caustics == Caustics::Path) return false;
    if (settings.caustics == Caustics::Auto && settings.clampIndirect > 0.0f) return false;
    return settings.integrator == Integrator::Nee ||
           (settings.split && settings.split->integrator == Integrator::Nee);
}

Renderer::Renderer(const Scene& scene, ShaderLibrary shaders, const BvhBuildOptions& bvhOptions,
                   SceneReads reads, CasterSearch casters)
    : shaders_(std::move(shaders)) {
    stats_.sceneReads = resolveSceneReads(reads);  // before the slow work, so that a refusal is quick
    auto start = SteadyClock::now();
    const double cpuStart = processCpuSeconds();  // CPU time of the whole process, so of every build thread
    AabbArray bounds;
    bounds.reserve(scene.triangles.size());
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    Bvh bvh = buildBinnedSah(bounds, bvhOptions);
    // Instanced meshes get a BVH each, in their own space (the top level is built when packing).
    std::vector<Bvh> meshBvhs;
    if (!scene.instances.empty())
        for (const InstancedMesh& mesh : scene.meshes) {
            AabbArray meshBounds;
            meshBounds.reserve(mesh.triangles.size());
            for (const Triangle& t : mesh.triangles) meshBounds.push_back(t.bounds());
            meshBvhs.push_back(buildBinnedSah(meshBounds, bvhOptions));
        }
    stats_.bvhBuildSeconds = secondsSince(start);
    stats_.bvhBuildCpuSeconds = processCpuSeconds() - cpuStart;
    stats_.bvhBuildThreads = buildThreadCount(bvhOptions);
    // SAH cost with unit node and triangle costs, whatever the build was tuned with, so that figures
    // compare between builds and commits.
    stats_.bvh = computeStats(bvh);

    start = SteadyClock::now();
    closeEmitters_ = emittersFaceCloseSurfaces(scene, bvh, meshBvhs);
    castersSearched_ = casters == CasterSearch::Run;
    if (castersSearched_) causticCasters_ = causticCasterSpheres(scene);
    PackedScene packed = packScene(scene, bvh, meshBvhs);
    stats_.triangles = uint32_t(scene.triangleCount());
    stats_.storedTriangles = packed.triangleCount;
    stats_.instances = uint32_t(scene.instances.size());
    instanceNodeStart_ = packed.instanceNodeStart;
    stats_.emitters = packed.lightCount - packed.punctualCount;
    stats_.punctualLights = packed.punctualCount;
    stats_.gpuBytes = packed.bytes();
    stats_.gpuGeometryBytes = packed.geometryBytes();
    stats_.gpuTextureBytes = packed.textureBytes();
    surfaceTextures_ = packed.hasTextures();
    surfaceMaps_ = packed.surfaceMaps;
    surfaceOpacity_ = packed.opacity;
    texcoordSlots_ = packed.texcoordSlots;
    textureSampling_ = packed.textureSampling;
    vertexColors_ = !packed.colors.empty();
    stats_.stackSize = layout::traversalStackEntries(packed.stackEntries);
    lightCount_ = packed.lightCount;
    punctualCount_ = packed.punctualCount;
    lightTreeFirst_ = packed.lightTreeFirst;
    lightTreeDepth_ = packed.lightTreeDepth;
    textures_ = std::make_unique<SceneTextures>(std::move(packed));
    stats_.uploadSeconds = secondsSince(start);
    stats_.gpuPinnedBytes = textures_->pinnedBytes();

    environmentColor_ = scene.environment.hasMap() ? glm::vec3(0.0f) : scene.environment.color;
    environmentRotation_ = glm::radians(scene.environment.rotationDegrees);
    if (scene.environment.hasMap()) {
        PackedEnvironment environment = packEnvironment(scene.environment);
        // A black map is no light at all: leave it out rather than sample nothing.
        if (environment.totalWeight > 0.0)
            environmentTextures_ = std::make_unique<EnvironmentTextures>(environment);
    }
    const bool vertexColors = hasVertexColors(scene);
    for (const Material& m : scene.materials) {
        const Material shaded = shaderMaterial(m, vertexColors);
        materialTypes_ |= 1u << uint32_t(shaded.type);
        absorbingGlass_ =
            absorbingGlass_ || (m.type == MaterialType::Dielectric && m.absorption != glm::vec3(0.0f));
        clearcoat_ = clearcoat_ || shaded.clearcoat > 0.0f;
        sheen_ = sheen_ || shaded.sheenColor != glm::vec3(0.0f);
    }
    glGenVertexArrays(1, &vertexArray_);
}

Renderer::~Renderer() {
    glDeleteVertexArrays(1, &vertexArray_);
}

std::unique_ptr<Program> Renderer::compile(Integrator integrator, const char* fragmentShader) const {
    ShaderDefines defines = layout::layoutDefines(stats_.sceneReads == SceneReads::Images);
    for (const auto& d : LightSplat::defines()) defines.push_back(d);
    defines.emplace_back("BVH_STACK_SIZE", std::to_string(stats_.stackSize));
    defines.emplace_back("BDPT_MAX_DEPTH", std::to_string(integratorFacts(Integrator::Bdpt).depthCap));
    defines.emplace_back("INTEGRATOR_FILE",
                         std::string("\"integrators/") + integratorName(integrator) + ".glsl\"");
    defines.emplace_back("DEBUG_VIEW", std::to_string(int(settings_.view)));
    defines.emplace_back("SAMPLER", settings_.sampler == Sampler::Sobol ? "1" : "0");
    bool solidAngle = settings_.lightSampling == LightSampling::SolidAngle ||
                      (settings_.lightSampling == LightSampling::Auto && closeEmitters_);
    defines.emplace_back("SPHERICAL_LIGHT_SAMPLING", solidAngle ? "1" : "0");
    // The light tree: nee's, when asked for or (auto) in a scene of many emitters (pack/light_strategy.h).
    bool tree = integrator == Integrator::Nee && lightTreeFirst_ > 0 &&
                (settings_.lightSelection == LightSelection::Tree ||
                 (settings_.lightSelection == LightSelection::Auto && lightTreePays(stats_.emitters)));
    defines.emplace_back("LIGHT_TREE", tree ? "1" : "0");
    if (tree) {
        defines.emplace_back("LIGHT_TREE_FIRST", std::to_string(lightTreeFirst_));
        defines.emplace_back("LIGHT_TREE_DEPTH", std::to_string(lightTreeDepth_));
    }
    defines.emplace_back("CAUSTICS_LIGHT_TRACED", causticsByLight(integrator, settings_) ? "1" : "0");
    defines.emplace_back("MAX_CAUSTIC_CASTERS", std::to_string(kMaxCausticCasters));
    defines.emplace_back("CAUSTIC_SMOOTH_BOUNCES", std::to_string(kCausticSmoothBounces));
    defines.emplace_back("GUIDES", settings_.guides ? "1" : "0");
    defines.emplace_back("MATERIAL_TYPES", std::to_string(materialTypes_));
    // Only scenes with an absorbing glass (KHR_materials_volume) attenuate paths inside (surface.glsl).
    defines.emplace_back("MATERIAL_VOLUME", absorbingGlass_ ? "1" : "0");
    // Only scenes with a clearcoat (KHR_materials_clearcoat) compile its lobe (bsdf.glsl).
    defines.emplace_back("MATERIAL_CLEARCOAT", clearcoat_ ? "1" : "0");
    defines.emplace_back("MATERIAL_SHEEN", sheen_ ? "1" : "0");  // and a sheen (KHR_materials_sheen)
    defines.emplace_back("ENVIRONMENT_MAP", environmentTextures_ ? "1" : "0");
    if (environmentTextures_) {
        glm::ivec2 size = environmentTextures_->size();
        defines.emplace_back("ENVIRONMENT_SIZE",
                             "ivec2(" + std::to_string(size.x) + ", " + std::to_string(size.y) + ")");
    }
    // Only textured scenes pay for texture lookups (glsl/common/textures.glsl).
    if (surfaceTextures_) {
        defines.emplace_back("SURFACE_TEXTURES", "1");
        defines.emplace_back("SURFACE_MAPS", std::to_string(surfaceMaps_));
        defines.emplace_back("TEXCOORD_SLOTS", std::to_string(texcoordSlots_));
        if (textureSampling_) defines.emplace_back("TEXTURE_SAMPLING", "1");
    }
    // Only scenes with vertex colours read them (glsl/common/textures.glsl).
    if (vertexColors_) defines.emplace_back("VERTEX_COLORS", "1");
    // Only scenes with alpha or single-sided materials test hits during traversal (common/opacity.glsl).
    if (surfaceOpacity_) defines.emplace_back("SURFACE_OPACITY", "1");
    // Only scenes with instances traverse two levels (glsl/common/intersect.glsl).
    if (instanceNodeStart_ > 0)
        defines.emplace_back("INSTANCE_NODES_START", std::to_string(instanceNodeStart_) + "u");
    // Only scenes with point, spot or directional lights compile their sampling (glsl/common/lights.glsl).
    defines.emplace_back("PUNCTUAL_LIGHTS", punctualCount_ > 0 ? "1" : "0");
    auto vec3Literal = [](const glm::vec3& v) {
        char text[96];
        std::snprintf(text, sizeof text, "vec3(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
        return std::string(text);
    };
    defines.emplace_back("SPECTRUM_MIN_NM", std::to_string(spectrum::kMinNm));
    defines.emplace_back("SPECTRUM_MAX_NM", std::to_string(spectrum::kMaxNm));
    defines.emplace_back("SPECTRUM_CENTRE_NM", vec3Literal(spectrum::kCentreNm));
    defines.emplace_back("SPECTRUM_WIDTH_NM", vec3Literal(spectrum::kWidthNm));
    defines.emplace_back("SPECTRUM_NORMALISATION", vec3Literal(spectrum::normalisation()));
    return std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", fragmentShader, defines);
}

// Whether nee leaves caustics seen directly to a light pass (settings/render_settings.h, Caustics):
// asked for, or (auto) in a scene with caustic casters and a light for the light paths to start from,
// unless the indirect light is clamped (the light pass's caustics would escape the clamp).
bool Renderer::causticsByLight(Integrator integrator, const RenderSettings& settings) const {
    if (integrator != Integrator::Nee || settings.view != View::Radiance) return false;
    if (settings.caustics == Caustics::Auto)
        return !causticCasters_.empty() && lightCount_ > 0 && settings.clampIndirect == 0.0f;
    return settings.caustics == Caustics::Light;
}

// Compiles every program settings_ needs (bdpt's radiance and nee's light-traced caustics add the
// light-tracing pass) and only then replaces the current ones, so that a compile error changes nothing.
void Renderer::compilePrograms(const RenderSettings& settings) {
    auto camera = [&](Integrator i) { return compile(i, "passes/trace.frag.glsl"); };
    auto light = [&](Integrator i) -> std::unique_ptr<Program> {
        bool splats =
            (i == Integrator::Bdpt && settings.view == View::Radiance) || causticsByLight(i, settings);
        return splats ? compile(i, "passes/light_trace.frag.glsl") : nullptr;
    };
    std::unique_ptr<Program> program = camera(settings.integrator), lightProgram = light(settings.integrator);
    std::unique_ptr<Program> split, splitLight;
    if (settings.split) {
        split = camera(settings.split->integrator);
        splitLight = light(settings.split->integrator);
    }
    program_ = std::move(program);
    splitProgram_ = std::move(split);
    lightProgram_ = std::move(lightProgram);
    splitLightProgram_ = std::move(splitLight);
}

// The light image (and its splat program) when a light-tracing program is in use, at the image's size;
// `rebuild` recompiles the splat program even if the size is unchanged.
size_t Renderer::imageBytes() const {
    return (targets_ ? targets_->bytes() : 0) + (lightSplat_ ? lightSplat_->bytes() : 0);
}

void Renderer::updateLightSplat(bool rebuild) {
    if (!lightProgram_ && !splitLightProgram_) {
        lightSplat_.reset();
        return;
    }
    if (lightSplat_ && !rebuild && lightSplat_->width() == settings_.width &&
        lightSplat_->height() == settings_.height)
        return;
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));  // never rebind a scene texture's unit
    auto lightSplat = std::make_unique<LightSplat>(shaders_, settings_.width, settings_.height);
    lightSplat_ = std::move(lightSplat);
}

void Renderer::reloadShaders() {
    compilePrograms(settings_);
    updateLightSplat(true);
    samples_ = 0;
    nextTile_ = 0;
    if (targets_) targets_->clear();
    resetLightImage(0);
}

void Renderer::resetLightImage(int restoredSamples) {
    if (lightSplat_) lightSplat_->clear();
    restoredLightPaths_ = restoredSamples;
    launchedLightPaths_ = 0;
}

double Renderer::lightPathsPerPixel() const {
    if (!lightSplat_) return 0.0;
    return double(restoredLightPaths_) +
           double(launchedLightPaths_) / (double(settings_.width) * double(settings_.height));
}

void Renderer::configure(const RenderSettings& settings, const Camera& camera) {
    checkSettings(settings);  // each setting's range or choices (settings/setting_table.h)
    if (settings.split)
        checkSetting(*findSetting("max_depth"), settings.split->maxDepth, "the split's max depth");
    for (Integrator i :
         {settings.integrator, settings.split ? settings.split->integrator : settings.integrator})
        if (settings.clampIndirect > 0.0f && !integratorFacts(i).clampsIndirect)
            throw Error(std::string("the indirect clamp is not implemented for ") + integratorName(i) +
                        " (its strategies share paths)");
    if (settings.caustics == Caustics::Light && settings.clampIndirect > 0.0f)
        throw Error("light-traced caustics are not clamped: use --caustics path with --clamp-indirect");
    if (!castersSearched_ && usesCausticCasters(settings))
        throw Error(
            "internal: these settings use the caustic casters, and the renderer was built without "
            "them (CasterSearch::Skip)");
    if (settings.caustics == Caustics::Light && causticCasters_.empty())
        throw Error(
            "light-traced caustics need a surface with a smooth (delta) lobe, glass or a mirror, "
            "and this scene has none");
    if (settings.caustics == Caustics::Light && lightCount_ == 0)
        throw Error("light-traced caustics need an emitter or a punctual light, and this scene has none");
    if (settings.lightSelection == LightSelection::Tree && lightTreeFirst_ == 0)
        throw Error(punctualCount_ > 0
                        ? "the light tree does not bound point, spot or directional lights, and "
                          "this scene has some: use --light-selection power"
                    : stats_.emitters == 0
                        ? "the light tree needs emitter triangles, and this scene has none"
                        : "the light tree holds at most " + std::to_string(layout::kMaxLightTreeEmitters) +
                              " emitter triangles; this scene has " + std::to_string(stats_.emitters));
    // The request and the scene file check the camera (validateCamera); the viewer's panel too, but a
    // focus distance left to the eye-target distance can still overflow.
    if (!(camera.aperture >= 0.0f) || !std::isfinite(camera.aperture))
        throw Error("the aperture must be a finite number, 0 (a pinhole) or more");
    float focus = resolvedFocusDistance(camera);
    if (camera.aperture > 0.0f && !(focus > 0.0f && std::isfinite(focus)))
        throw Error("the focus distance must be a finite number above 0");
    bool splitChanged = settings.split.has_value() != settings_.split.has_value() ||
                        (settings.split && settings.split->integrator != settings_.split->integrator);
    const bool recompile = !program_ || !sameSettings(settings, settings_, kRecompiles) || splitChanged;
    // An integrator that traces fewer bounces than asked says so, once per change.
    if (!program_ || settings.maxDepth != settings_.maxDepth || settings.integrator != settings_.integrator)
        if (auto capped = depthCapNote(settings.integrator, settings.maxDepth)) note(*capped);
    if (recompile) {
        // Compile both programs before changing anything, so that a compile error leaves the renderer
        // exactly as it was.
        RenderSettings previous = settings_;
        settings_ = settings;  // compile() reads the view from the settings
        try {
            compilePrograms(settings);
        } catch (...) {
            settings_ = previous;
            throw;
        }
        // Delta lights cannot be hit, and these two find light only by hitting it (glsl/integrators/).
        for (Integrator i :
             {settings.integrator, settings.split ? settings.split->integrator : settings.integrator})
            if (punctualCount_ > 0 && settings.view == View::Radiance &&
                (i == Integrator::Naive || i == Integrator::Bsdf)) {
                warn(std::string("the ") + integratorName(i) + " integrator cannot see the scene's " +
                     std::to_string(punctualCount_) +
                     " point, spot or directional light(s): no ray can hit a light of no size; they light "
                     "the image only with nee or bdpt");
                break;
            }
    }
    if (!targets_ || targets_->width() != settings.width || targets_->height() != settings.height) {
        glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));  // never rebind a scene texture's unit
        targets_.reset();
        targets_ = std::make_unique<RenderTargets>(settings.width, settings.height);
    }
    settings_ = settings;
    updateLightSplat(false);
    camera_ = camera;
    targets_->clear();
    resetLightImage(0);
    samples_ = 0;
    passes_ = 0;
    pacer_ = PassPacer(settings.samplesPerPass, RenderSettings::kMaxSamplesPerPass);
    nextTile_ = 0;
}

// Every uniform of the trace passes (camera and light tracing) that does not depend on the pass is set
// here, and only here; the scene textures are bound.
void Renderer::setTraceUniforms(Program& p, int maxDepth) {
    p.use();
    p.set("uTriangles", int(layout::kTrianglesUnit));
    p.set("uNormals", int(layout::kNormalsUnit));
    p.set("uNodes", int(layout::kNodesUnit));
    p.set("uMaterials", int(layout::kMaterialsUnit));
    p.set("uLights", int(layout::kLightsUnit));
    p.set("uLightCount", int(lightCount_));
    if (surfaceTextures_) {
        p.set("uTexcoords", int(layout::kTexcoordsUnit));
        p.set("uTextureTexels", int(layout::kTextureTexelsUnit));
        p.set("uTextureTable", int(layout::kTextureTableUnit));
        if (surfaceMaps_ & layout::kNormalMapBit) p.set("uTangents", int(layout::kTangentsUnit));
    }
    if (vertexColors_) p.set("uColors", int(layout::kColorsUnit));
    p.set("uEnvironment", environmentColor_);
    if (environmentTextures_) {
        p.set("uEnvironmentMap", int(layout::kEnvironmentMapUnit));
        p.set("uEnvironmentCdf", int(layout::kEnvironmentCdfUnit));
        p.set("uEnvironmentRotation", environmentRotation_);
        environmentTextures_->bind(stats_.sceneReads);
    }
    p.set("uCasters", causticCasters_);
    p.set("uCasterCount", int(causticCasters_.size()));
    p.set("uMaxDepth", maxDepth);
    p.set("uSeed", settings_.seed);
    p.set("uClampIndirect", settings_.clampIndirect);

    // Camera basis: right and up are scaled so that normalised device coordinates map onto the image plane.
    CameraFrame frame = cameraFrame(camera_, float(settings_.width) / float(settings_.height));
    p.set("uCameraEye", frame.eye);
    p.set("uCameraForward", frame.forward);
    p.set("uCameraRight", frame.right);
    p.set("uCameraUp", frame.up);
    p.set("uLensRadius", frame.lensRadius);
    p.set("uFocusDistance", frame.focusDistance);
    p.set("uResolution", glm::vec2(settings_.width, settings_.height));
    textures_->bind(stats_.sceneReads);
}

// The camera pass: `samples` samples per pixel over `region`, added to the accumulation.
void Renderer::draw(Program& p, int maxDepth, const PixelRegion& region, int samples) {
    if (region.empty()) return;
    setTraceUniforms(p, maxDepth);
    p.set("uPreviousSum", kSumUnit);
    p.set("uPreviousSquares", kSumUnit + kSquaresAttachment);
    p.set("uPreviousCounters", kSumUnit + kCountersAttachment);
    p.set("uPreviousNormalDepth", kSumUnit + kNormalDepthAttachment);
    p.set("uPreviousAlbedo", kSumUnit + kAlbedoAttachment);
    p.set("uSampleOffset", settings_.sampleOffset);
    p.set("uSamplesPerPass", samples);
    glBindVertexArray(vertexArray_);
    targets_->beginPass(kSumUnit, region);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    targets_->endPass(region);
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
}

// The intersection of two regions.
static PixelRegion clip(const PixelRegion& a, const PixelRegion& b) {
    int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    int x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

void Renderer::drawPass(const PixelRegion& area, int samples) {
    struct Part {
        Program* camera;
        Program* light;
        int maxDepth;
        PixelRegion region;
        Integrator integrator;
    };
    PixelRegion full = targets_->full();
    int half = settings_.width / 2;
    std::vector<Part> parts;
    if (splitProgram_) {
        parts.push_back({program_.get(), lightProgram_.get(), settings_.maxDepth,
                         clip(full, {0, 0, half, settings_.height}), settings_.integrator});
        parts.push_back({splitProgram_.get(), splitLightProgram_.get(), settings_.split->maxDepth,
                         clip(full, {half, 0, settings_.width, settings_.height}),
                         settings_.split->integrator});
    } else {
        parts.push_back(
            {program_.get(), lightProgram_.get(), settings_.maxDepth, full, settings_.integrator});
    }
    for (const Part& part : parts) draw(*part.camera, part.maxDepth, clip(area, part.region), samples);
    if (!lightSplat_) return;
    // The light paths of these samples, launched from every pixel of `area` (so that each light path
    // per pixel of N is traced once, whatever the tiling) and splatted anywhere in the part's half.
    for (const Part& part : parts) {
        if (!part.light) continue;
        setTraceUniforms(*part.light, part.maxDepth);
        // nee's caustic light paths leave from one pixel in kCausticLaunchStride, and their records of
        // strategies s = 1 and 2 are empty (glsl/passes/light_trace.frag.glsl).
        bool caustic = part.integrator == Integrator::Nee;
        LightSplat::Launch launch{caustic ? kCausticLaunchStride : 1, caustic ? 2 : 0};
        for (int i = 0; i < samples; ++i)
            lightSplat_->trace(*part.light, settings_.sampleOffset + uint32_t(samples_ + i), area,
                               part.region, launch);
    }
    launchedLightPaths_ += uint64_t(area.width) * uint64_t(area.height) * uint64_t(samples);
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
}

void Renderer::render(int samples, const std::function<bool(int)>& progress) {
    if (!targets_) throw Error("internal: Renderer::render before configure");
    int done = 0;
    while (done < samples) {
        int count = pacer_.next(samples - done);
        auto start = SteadyClock::now();
        drawPass(targets_->full(), count);
        glFinish();  // so that progress and timing see finished work, not queued commands
        pacer_.record(count, secondsSince(start));
        ++passes_;
        samples_ += count;
        done += count;
        if (progress && !progress(done)) break;
    }
}

bool Renderer::renderTile(int tileSize) {
    if (!targets_) throw Error("internal: Renderer::renderTile before configure");
    tileSize = std::max(tileSize, 1);
    int columns = (settings_.width + tileSize - 1) / tileSize,
        rows = (settings_.height + tileSize - 1) / tileSize;
    int column = nextTile_ % columns, row = nextTile_ / columns;
    drawPass(clip(targets_->full(), {column * tileSize, row * tileSize, tileSize, tileSize}), 1);
    if (++nextTile_ < columns * rows) return false;
    nextTile_ = 0;
    ++samples_;
    return true;
}

void Renderer::restore(const Image& mean, int samples) {
    if (!targets_) throw Error("internal: Renderer::restore before configure");
    if (mean.width != settings_.width || mean.height != settings_.height)
        throw Error("the saved render is " + std::to_string(mean.width) + "x" + std::to_string(mean.height) +
                    ", not " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height));
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
    targets_->restore(mean, samples);
    resetLightImage(samples);
    samples_ = samples;
    nextTile_ = 0;
}

Accumulation Renderer::readback() const {
    if (!targets_) throw Error("internal: Renderer::readback before configure");
    Accumulation acc = targets_->read();
    if (lightSplat_) {
        lightSplat_->read(acc.splatSum, acc.splatSquares);
        acc.lightPathsPerPixel = lightPathsPerPixel();
    }
    return acc;
}

AccumulationTextures Renderer::textures() const {
    if (!targets_) throw Error("internal: Renderer::textures before configure");
    return {targets_->sumTexture(), lightSplat_ ? lightSplat_->sumTexture() : 0u, float(lightPathsPerPixel()),
            lightSplat_ ? lightSplat_->squaresTexture() : 0u};
}

}  // namespace fp
