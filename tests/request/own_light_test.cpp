// Whether a scene's emitters light it (scene/own_light.h): a closed room's lamp does, as OBJ and as
// glTF; glowing detail on a model's outside does not; a bright lamp over an open floor does.
#include <gtest/gtest.h>

#include <fstream>

#include "core/log.h"
#include "request/default_light.h"
#include "request/own_light.h"
#include "scene/gltf_test_util.h"
#include "scene/lighting.h"
#include "scene/load.h"
#include "scene/procedural.h"
#include "scene/scene_test_util.h"

namespace fp {
namespace {

std::string cornellObj() {
    return std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.obj";
}

// `scene`'s triangles as a .gltf: a primitive per material, positions only, each material's diffuse as
// its base colour and its emission as emissiveFactor (scaled into [0, 1]) times
// KHR_materials_emissive_strength, as a user's exporter writes an OBJ room.
std::string asGltf(const Scene& scene) {
    test::GltfBuilder b;
    nlohmann::json primitives = nlohmann::json::array();
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        std::vector<glm::vec3> positions;
        for (const Triangle& t : scene.triangles)
            if (t.material == m) positions.insert(positions.end(), t.p.begin(), t.p.end());
        if (positions.empty()) continue;
        const Material& material = scene.materials[m];
        nlohmann::json g = {
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {material.diffuse.x, material.diffuse.y, material.diffuse.z, 1.0}},
              {"metallicFactor", 0.0}}}};
        const float strength = std::max({material.emission.x, material.emission.y, material.emission.z});
        if (strength > 0.0f) {
            const glm::vec3 factor = material.emission / strength;
            g["emissiveFactor"] = {factor.x, factor.y, factor.z};
            g["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}};
        }
        primitives.push_back(
            {{"attributes", {{"POSITION", b.vec3(positions)}}}, {"material", b.material(g)}});
    }
    b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    b.scene({b.node({{"mesh", b.mesh(primitives)}})});
    return b.gltf();
}

// A closed sphere (its faces outward) of radius 1, Lambertian grey, whose triangles above `capHeight`
// (in y) are of material 1, emissive `glow`: a model with a glowing part.
Scene glowingSphere(float capHeight, const glm::vec3& glow) {
    Scene scene;
    scene.source = "glowing sphere";
    Material grey, lamp;
    lamp.emission = glow;
    scene.materials = {grey, lamp};
    appendSphere(scene, glm::vec3(0.0f), 1.0f, 24, 48, 0, true);
    for (Triangle& t : scene.triangles)
        if ((t.p[0].y + t.p[1].y + t.p[2].y) / 3.0f > capHeight) t.material = 1;
    return scene;
}

// The Cornell box as OBJ: its lamp lights the room, whose open front lets out about a third of the light
// (0.69 stays for two bounces, measured), and the lamp's light on the walls is above the studio's
// (1.3x). Thresholds 0.4 and 0.5: a room whose measures fell to those would still pass.
TEST(OwnLight, TheCornellBoxIsLitByItsLamp) {
    const OwnLightEstimate e = estimateOwnLight(loadScene(cornellObj()));
    EXPECT_GT(e.enclosure, 0.6);
    EXPECT_GT(e.ownToStudio, 1.0);
    EXPECT_TRUE(e.lightsTheScene());
}

TEST(OwnLight, TheCornellBoxAsGltfIsLitByItsLamp) {
    test::TempDir dir;
    const Scene gltf = loadScene(dir.write("cornell.gltf", asGltf(loadScene(cornellObj()))));
    ASSERT_EQ(gltf.triangles.size(), loadScene(cornellObj()).triangles.size());
    const OwnLightEstimate e = estimateOwnLight(gltf);
    EXPECT_GT(e.enclosure, 0.6);
    EXPECT_GT(e.ownToStudio, 1.0);
    EXPECT_TRUE(e.lightsTheScene());
    // So the default light leaves it alone: no environment, no note.
    Scene lit = gltf;
    WarningCapture capture;
    EXPECT_FALSE(lightIfUnlit(lit));
    EXPECT_TRUE(lit.environment.isBlack());
    EXPECT_TRUE(capture.notes().empty());
}

TEST(OwnLight, TheProjectsLitRoomsAreLitByTheirLamps) {
    for (const char* file :
         {"/assets/cornell_spheres/cornell_spheres.json", "/assets/many_lights/many_lights.json"})
        EXPECT_TRUE(estimateOwnLight(loadScene(std::string(FP_SOURCE_DIR) + file)).lightsTheScene()) << file;
    EXPECT_TRUE(estimateOwnLight(benchmarkSphereScene(1000)).lightsTheScene());
    EXPECT_TRUE(estimateOwnLight(randomTriangleSoup(1000, 1)).lightsTheScene());
}

// A model whose visor glows: the glow leaves the model at once, whatever its radiance; and a model
// glowing all over (a helmet with an emissive texture on every triangle) does not light itself either.
TEST(OwnLight, GlowingDetailOnAModelsOutsideDoesNotLightIt) {
    for (float glow : {1.0f, 20.0f}) {
        const OwnLightEstimate e = estimateOwnLight(glowingSphere(0.8f, glm::vec3(glow)));
        EXPECT_LT(e.enclosure, 0.05) << glow;
        EXPECT_LT(e.ownToStudio, 0.05) << glow;
        EXPECT_FALSE(e.lightsTheScene()) << glow;
    }
    EXPECT_FALSE(estimateOwnLight(glowingSphere(-2.0f, glm::vec3(1.0f))).lightsTheScene());
}

// A lamp over an open floor lights it when it is bright: the floor's irradiance from the lamp then
// rivals the studio's, though nearly all of the lamp's light leaves the open scene.
TEST(OwnLight, ABrightLampOverAnOpenFloorLightsIt) {
    Scene dim = causticScene(0.0f);  // a 0.2 x 0.2 lamp of radiance 100, 3 above a 6 x 6 floor
    const OwnLightEstimate weak = estimateOwnLight(dim);
    EXPECT_LT(weak.enclosure, 0.1) << "open: the floor's light escapes";
    EXPECT_LT(weak.ownToStudio, 0.3);
    EXPECT_FALSE(weak.lightsTheScene());
    Scene bright = dim;
    for (Material& m : bright.materials) m.emission *= 10.0f;
    const OwnLightEstimate strong = estimateOwnLight(bright);
    EXPECT_NEAR(strong.ownToStudio, 10.0 * weak.ownToStudio, 1e-9) << "the same rays, ten times the lamp";
    EXPECT_TRUE(strong.lightsTheScene());
}

TEST(OwnLight, TheEstimateIsTheSameEveryTimeAndZeroWithoutEmitters) {
    const Scene scene = loadScene(cornellObj());
    const OwnLightEstimate a = estimateOwnLight(scene), b = estimateOwnLight(scene);
    EXPECT_EQ(a.enclosure, b.enclosure);
    EXPECT_EQ(a.ownToStudio, b.ownToStudio);
    Scene dark = scene;
    for (Material& m : dark.materials) m.emission = glm::vec3(0.0f);
    const OwnLightEstimate none = estimateOwnLight(dark);
    EXPECT_EQ(none.enclosure, 0.0);
    EXPECT_EQ(none.ownToStudio, 0.0);
}

}  // namespace
}  // namespace fp
