// The study's scene set: the names it is chosen by, the files it reads, and the environment-lit scene
// it builds in code.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "scene/procedural.h"
#include "study/plots.h"
#include "study/scene_set.h"

namespace fp::study {
namespace {

TEST(SceneSet, NamesAndSelection) {
    std::vector<StudyScene> set = studySceneSet(defaultAssetDir());
    std::vector<std::string> names;
    for (const StudyScene& s : set) names.push_back(s.name);
    EXPECT_EQ(names, (std::vector<std::string>{"cornell", "cornell-checker", "cornell-spheres", "environment",
                                               "sphere-1m", "gltf-showcase"}));
    std::vector<StudyScene> two = selectScenes(set, "environment,cornell");
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].name, "environment");
    EXPECT_EQ(two[1].name, "cornell");
    EXPECT_THROW(selectScenes(set, "cornell,teapot"), Error);
    EXPECT_THROW(selectScenes(set, "cornell,cornell"), Error);
    EXPECT_EQ(sceneNameOf("assets/gltf_showcase/showcase.json"), "showcase");
    EXPECT_EQ(referenceFileName("sphere-1m"), "reference_sphere-1m.exr");
    EXPECT_EQ(stripFileName("cornell"), "strip_cornell.png");
}

TEST(SceneSet, FileScenesLoadFromTheAssetDirectory) {
    // The textured scene has its texture; a missing directory fails with a message, not a crash.
    std::vector<StudyScene> set = selectScenes(studySceneSet(defaultAssetDir()), "cornell-checker");
    Scene checker = set[0].load();
    EXPECT_FALSE(checker.textures.empty());
    std::vector<StudyScene> nowhere = selectScenes(studySceneSet("/nonexistent"), "gltf-showcase");
    try {
        nowhere[0].load();
        FAIL() << "loaded a scene from a missing directory";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/gltf_showcase/showcase.json"), std::string::npos)
            << e.what();
    }
}

TEST(SceneSet, EnvironmentSceneIsLitByItsMapAlone) {
    Scene scene = environmentLitScene();
    // A two-triangle ground and three spheres of 2 x 48 x (24 - 1) = 2208 triangles: 6626.
    EXPECT_EQ(scene.triangleCount(), 6626u);
    EXPECT_TRUE(scene.environment.hasMap());
    for (const Material& m : scene.materials) EXPECT_EQ(m.emission, glm::vec3(0.0f)) << m.name;
    // The sun: the map's brightest texel, far above the sky around it.
    EXPECT_GT(scene.environment.map.at(61, 21).g, 100.0f);
    EXPECT_LT(scene.environment.map.at(10, 21).g, 1.0f);
}

TEST(SceneSet, PlotsSelectEachScenesRows) {
    StudyRow a;
    a.scene = "cornell";
    a.integrator = "nee";
    a.denoiser = "none";
    a.spp = 1;
    a.relMse = 0.1;
    StudyRow b = a;
    b.scene = "environment";
    std::string script = gnuplotScript({a, b}, 4e-4);
    EXPECT_NE(script.find("strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'none'"),
              std::string::npos);
    EXPECT_NE(script.find("set output 'environment_error_vs_time.png'"), std::string::npos);
    EXPECT_EQ(plotFileNames("cornell")[0], "cornell_error_vs_spp.png");
}

}  // namespace
}  // namespace fp::study
