// Each GLSL file that passes include (one without a main()) #includes what it uses, so that it compiles
// whatever a pass includes before it. The test compiles every such file alone: a fragment shader of
// `#include "<file>"` and an empty main(), with the defines the passes that include it get. A file that
// leans on an include it does not make (a function, struct, define or uniform of another file) fails
// here, naming the missing identifier at glsl/<file>:<line>.
//
// Two sets of defines. The scene passes' (the trace and light-tracing passes and the files they
// include): the renderer's own, got by putting the probe in place of passes/trace.frag.glsl in a copy
// of the shaders (and an empty shader in place of passes/light_trace.frag.glsl, which gets the same
// defines) and letting the Renderer compile it, for scenes and settings that switch on every optional
// part (textures and every map, coverage, instances, punctual lights, an environment map, every
// material type, light-traced caustics, guides), then for the Cornell box with the light tree and
// texel fetches, and with each debug view (only the files that name DEBUG_VIEW). The other passes'
// (display, denoise, realtime, the light splats): no scene defines.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/program.h"
#include "render/light_splat.h"
#include "render_test_util.h"
#include "surface_maps_scene.h"

namespace fp::test {
namespace {

namespace fs = std::filesystem;

bool isPass(const std::string& text) {
    return text.find("void main(") != std::string::npos;
}

// The shaders the tests use (testShaders(): FP_RENDER_TEST_SHADERS, else the source tree's), by path below
// glsl/.
std::map<std::string, std::string> testShaderFiles() {
    const std::string dir = test::testShaderDirectory();
    const ShaderLibrary shaders = test::testShaders();
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().extension() == ".glsl") {
            const std::string path = entry.path().lexically_relative(dir).generic_string();
            files[path] = shaders.read(path);
        }
    return files;
}

// A copy of those shaders, which the probes can be written into; removed with the object.
class ShaderCopy {
  public:
    explicit ShaderCopy(const std::map<std::string, std::string>& files)
        : dir_(fs::temp_directory_path() / ("fragpath_glsl_includes_" + std::to_string(::getpid()))) {
        for (const auto& [path, text] : files) write(path, text);
        test::TestShaderSources::add(dir_.string());  // a copy of testShaders(), with the probes added
    }
    ~ShaderCopy() { fs::remove_all(dir_); }
    ShaderCopy(const ShaderCopy&) = delete;
    ShaderCopy& operator=(const ShaderCopy&) = delete;

    void write(const std::string& path, const std::string& text) const {
        fs::create_directories((dir_ / path).parent_path());
        std::ofstream(dir_ / path) << text;
    }
    ShaderLibrary library() const { return ShaderLibrary(dir_.string()); }

  private:
    fs::path dir_;
};

std::string probe(const std::string& file) {
    return "#include \"" + file + "\"\nout vec4 fpProbeColor;\nvoid main() { fpProbeColor = vec4(0.0); }\n";
}

// Every includable file, and those that the passes compiled without the scene's defines include.
struct Includables {
    std::vector<std::string> all;
    std::set<std::string> withoutSceneDefines;
};

Includables includables(const std::map<std::string, std::string>& files, const ShaderLibrary& shaders) {
    Includables out;
    for (const auto& [path, text] : files) {
        if (!isPass(text)) {
            out.all.push_back(path);
            continue;
        }
        const bool scenePass = path == "passes/trace.frag.glsl" || path == "passes/light_trace.frag.glsl";
        if (scenePass || path.rfind("tests/", 0) == 0) continue;
        for (const auto& [file, line] : shaders.expand(path, LightSplat::defines()).origins)
            if (file != path && file != "(generated)") out.withoutSceneDefines.insert(file);
    }
    return out;
}

// Every optional part of the scene passes at once: everyMapScene's maps, coverage and single-sided
// panel, plus an emission map, a second uv slot, a clamped nearest texture, vertex colours, an
// instanced mesh, a spot light, an environment map, and glass (absorbing), metal, clearcoat, sheen and
// unlit materials, the glass on a quad so that nee has a caustic caster.
Scene everyFeatureScene() {
    Scene scene = everyMapScene();
    scene.materials[2].emissionTexture = 0;
    Texture clamped = makeTexture("clamped", 1, 1, {255, 255, 255, 255});
    clamped.wrapS = TextureWrap::ClampToEdge;
    clamped.nearest = true;
    clamped.uvSlot = 1;
    scene.textures.push_back(clamped);
    scene.materials[3].diffuseTexture = int32_t(scene.textures.size() - 1);
    scene.texcoords1.assign(scene.triangles.size(),
                            {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(1.0f)});
    scene.colors.assign(scene.triangles.size(), {glm::vec4(1.0f), glm::vec4(0.5f), glm::vec4(1.0f)});
    Material glass;
    glass.type = MaterialType::Dielectric;
    glass.absorption = glm::vec3(0.2f);
    Material metal;
    metal.type = MaterialType::Conductor;
    metal.roughness = 0.1f;
    Material coated;
    coated.type = MaterialType::MetallicRoughness;
    coated.clearcoat = 1.0f;
    coated.sheenColor = glm::vec3(0.5f);
    Material unlit;
    unlit.type = MaterialType::Unlit;
    const uint32_t glassIndex = uint32_t(scene.materials.size());
    scene.materials.insert(scene.materials.end(), {glass, metal, coated, unlit});
    appendQuad(scene, glm::vec3(-0.5f, 1.0f, -1.0f), glm::vec3(0.5f, 1.0f, -1.0f),
               glm::vec3(0.5f, 1.5f, -1.0f), glm::vec3(-0.5f, 1.5f, -1.0f), glassIndex);
    scene.texcoords1.resize(scene.triangles.size());
    scene.colors.resize(scene.triangles.size(), {glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)});
    InstancedMesh mesh;
    mesh.name = "panel";
    Scene panel;
    appendQuad(panel, glm::vec3(0.0f), glm::vec3(0.2f, 0.0f, 0.0f), glm::vec3(0.2f, 0.2f, 0.0f),
               glm::vec3(0.0f, 0.2f, 0.0f), glassIndex + 1);
    mesh.triangles = panel.triangles;
    scene.meshes.push_back(mesh);
    for (float x : {1.0f, 1.5f}) {
        Instance instance;
        instance.objectToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.5f, 1.0f));
        scene.instances.push_back(instance);
    }
    PunctualLight spot;
    spot.type = PunctualLightType::Spot;
    spot.position = glm::vec3(0.0f, 2.0f, 0.0f);
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    scene.punctualLights.push_back(spot);
    scene.environment.map = Image(4, 2);
    for (glm::vec3& p : scene.environment.map.pixels) p = glm::vec3(0.5f);
    return scene;
}

struct SceneDefines {
    std::string name;
    Scene scene;
    Camera camera;
    RenderSettings settings;
    std::string switchedOn;       // a preprocessor condition the renderer's defines must meet
    bool texelFetch = false;      // read the scene with texelFetch instead of images (FRAGPATH_SCENE_READS)
    std::string onlyFilesNaming;  // if not empty, probe only the files whose text names it
};

std::vector<SceneDefines> sceneDefineSets() {
    RenderSettings small;
    small.width = small.height = 8;
    std::vector<SceneDefines> sets;
    SceneDefines every{"every feature", everyFeatureScene(), everyMapCamera(), small, "", false, ""};
    every.settings.caustics = Caustics::Light;
    every.settings.guides = true;
    every.switchedOn =
        "defined(SURFACE_TEXTURES) && SURFACE_MAPS == 63 && TEXCOORD_SLOTS == 2 && "
        "defined(TEXTURE_SAMPLING) && defined(VERTEX_COLORS) && defined(SURFACE_OPACITY) && "
        "defined(INSTANCE_NODES_START) && PUNCTUAL_LIGHTS && ENVIRONMENT_MAP && "
        "MATERIAL_TYPES == 63 && MATERIAL_VOLUME && MATERIAL_CLEARCOAT && MATERIAL_SHEEN && "
        "CAUSTICS_LIGHT_TRACED && GUIDES && defined(SCENE_READS_IMAGES)";
    sets.push_back(every);
    const Scene cornell = builtinCornellBox();
    SceneDefines tree{"light tree", cornell, *cornell.camera, small, "", true, ""};
    tree.settings.lightSelection = LightSelection::Tree;
    tree.settings.lightSampling = LightSampling::SolidAngle;
    tree.settings.sampler = Sampler::Independent;
    tree.switchedOn =
        "LIGHT_TREE && SPHERICAL_LIGHT_SAMPLING && SAMPLER == 0 && !defined(SCENE_READS_IMAGES) && "
        "!defined(SURFACE_TEXTURES) && !PUNCTUAL_LIGHTS && !CAUSTICS_LIGHT_TRACED";
    sets.push_back(tree);
    for (View view : {View::Depth, View::Normal, View::Bounces, View::Nodes, View::Triangles, View::Cost}) {
        SceneDefines one{std::string("view ") + viewName(view),        cornell, *cornell.camera, small,
                         "DEBUG_VIEW == " + std::to_string(int(view)), false,   "DEBUG_VIEW"};
        one.settings.view = view;
        sets.push_back(one);
    }
    return sets;
}

TEST(GlslIncludes, EveryIncludableFileCompilesAlone) {
    ensureGlContext();
    const std::map<std::string, std::string> shaderFiles = testShaderFiles();
    ShaderCopy copy(shaderFiles);
    const Includables files = includables(shaderFiles, copy.library());
    ASSERT_GT(files.all.size(), 20u);
    ASSERT_TRUE(files.withoutSceneDefines.count("denoise/pixel_class.glsl"));
    for (const std::string& file : files.withoutSceneDefines) {
        copy.write("include_probe.frag.glsl", probe(file));
        try {
            Program(copy.library(), "passes/fullscreen.vert.glsl", "include_probe.frag.glsl",
                    LightSplat::defines());
        } catch (const Error& e) {
            ADD_FAILURE() << file << " alone, without the scene's defines:\n" << e.what();
        }
    }
    for (const SceneDefines& set : sceneDefineSets()) {
        // First, that the scene and settings switch on what the set is for.
        copy.write("passes/trace.frag.glsl", "#if !(" + set.switchedOn +
                                                 ")\n#error not switched on\n#endif\n" +
                                                 probe("common/luminance.glsl"));
        // The light-tracing pass gets the same defines: an empty one is enough, and costs no compile time.
        copy.write("passes/light_trace.frag.glsl", probe("common/luminance.glsl"));
        ScopedEnv reads("FRAGPATH_SCENE_READS", set.texelFetch ? "texelFetch" : nullptr);
        Renderer renderer(set.scene, copy.library());
        try {
            renderer.configure(set.settings, set.camera);
        } catch (const Error& e) {
            ADD_FAILURE() << set.name << ": the renderer's defines do not meet " << set.switchedOn << "\n"
                          << e.what();
            continue;
        }
        for (const std::string& file : files.all) {
            if (!set.onlyFilesNaming.empty() &&
                shaderFiles.at(file).find(set.onlyFilesNaming) == std::string::npos)
                continue;
            copy.write("passes/trace.frag.glsl", probe(file));
            try {
                renderer.reloadShaders();
            } catch (const Error& e) {
                ADD_FAILURE() << file << " alone, with the defines of " << set.name << ":\n" << e.what();
            }
        }
    }
}

}  // namespace
}  // namespace fp::test
