// What lights a scene (scene/lighting.h): which scenes count as lit, the default sky a scene without
// light gets, and environment maps read from .hdr and .exr files.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <limits>

#include "image/exr.h"
#include "image/hdr.h"
#include "scene/lighting.h"
#include "scene/load.h"
#include "scene/studio_environment.h"
#include "scene_test_util.h"

namespace fp {
namespace {

TEST(Lighting, AnEmitterOrAnEnvironmentThatIsNotBlackLightsTheScene) {
    Scene scene = test::unlitTriangle();
    EXPECT_FALSE(hasLight(scene));
    // An emissive material no triangle uses lights nothing.
    Material lamp;
    lamp.emission = glm::vec3(0.0f, 0.0f, 2.0f);
    scene.materials.push_back(lamp);
    EXPECT_FALSE(hasLight(scene));
    scene.triangles[0].material = 1;
    EXPECT_TRUE(hasLight(scene));

    scene = test::unlitTriangle();
    scene.environment.color = glm::vec3(0.0f, 0.1f, 0.0f);
    EXPECT_TRUE(hasLight(scene));
    // A map: lit when some texel is and the intensity is positive.
    scene.environment.map = Image(4, 2);
    EXPECT_FALSE(hasLight(scene)) << "the map, black, replaces the colour";
    scene.environment.map.at(3, 1) = glm::vec3(0.5f, 0.0f, 0.0f);
    EXPECT_TRUE(hasLight(scene));
    scene.environment.intensity = 0.0f;
    EXPECT_FALSE(hasLight(scene));

    // A point, spot or directional light that is not black (issue 18: a scene lit only by a point light
    // must not get the default sky on top).
    scene = test::unlitTriangle();
    PunctualLight bulb;
    bulb.intensity = glm::vec3(0.0f);
    scene.punctualLights.push_back(bulb);
    EXPECT_FALSE(hasLight(scene)) << "a black light lights nothing";
    scene.punctualLights[0].intensity.z = 3.0f;
    EXPECT_TRUE(hasLight(scene));
    scene.punctualLights[0].type = PunctualLightType::Directional;
    EXPECT_TRUE(hasLight(scene));
}

TEST(Lighting, TheStudioEnvironmentIsNeutralAndOfModerateRange) {
    EXPECT_EQ(studioRadiance(glm::vec3(0, -1, 0)), glm::vec3(kStudioGround));
    EXPECT_EQ(studioRadiance(glm::vec3(0, 1, 0)), glm::vec3(kStudioZenith));
    EXPECT_EQ(studioRadiance(kStudioKeyDirection), glm::vec3(kStudioKey));
    EXPECT_EQ(studioRadiance(kStudioFillDirection), glm::vec3(kStudioFill));
    const Environment studio = studioEnvironment();
    ASSERT_EQ(studio.map.width, kStudioMapWidth);
    ASSERT_EQ(studio.map.height, kStudioMapHeight);
    float lo = 1e30f, hi = 0.0f;
    for (const glm::vec3& p : studio.map.pixels) {
        ASSERT_TRUE(p.x == p.y && p.y == p.z) << "neutral";
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
    }
    EXPECT_EQ(lo, kStudioGround);
    EXPECT_EQ(hi, kStudioKey) << "the key's centre falls between texel centres but within its flat core";
    EXPECT_LE(hi / lo, 20.0f);
    // Row 0 is straight up; the middle column looks along -z (u = 0.5), the first along +z.
    EXPECT_NEAR(studio.map.at(kStudioMapWidth / 2, 0).x, kStudioZenith, 1e-3f);
    EXPECT_NEAR(studio.map.at(0, kStudioMapHeight - 1).x, kStudioGround, 1e-6f);
}

TEST(Lighting, EnvironmentMapsAreHdrOrExrByExtension) {
    test::TempDir dir;
    Image sky(4, 2);
    for (size_t i = 0; i < sky.pixels.size(); ++i) sky.pixels[i] = glm::vec3(0.5f + float(i), 1.0f, 2.0f);
    writeExr(dir.path("sky.EXR"), sky);
    EXPECT_EQ(loadEnvironmentMap(dir.path("sky.EXR"), "label").pixels, sky.pixels);
    std::vector<float> rgb;
    for (const glm::vec3& p : sky.pixels) rgb.insert(rgb.end(), {p.x, p.y, p.z});
    ASSERT_TRUE(stbi_write_hdr(dir.path("sky.hdr").c_str(), 4, 2, 3, rgb.data()));
    EXPECT_EQ(loadEnvironmentMap(dir.path("sky.hdr"), "label").pixels, readHdr(dir.path("sky.hdr")).pixels);
    EXPECT_EQ(test::errorOf([&] { loadEnvironmentMap(dir.path("sky.png"), "--environment sky.png"); }),
              "--environment sky.png must be a Radiance .hdr or an OpenEXR .exr file");
    EXPECT_TRUE(isEnvironmentMapPath("a/b.Hdr"));
    EXPECT_FALSE(isEnvironmentMapPath("a/b.pfm"));
}

TEST(Lighting, NegativeAndNonFiniteTexelsOfAMapBecomeZeroWithAWarning) {
    test::TempDir dir;
    Image sky(3, 1);
    sky.at(0, 0) = glm::vec3(1.0f, -0.5f, 2.0f);
    sky.at(1, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 3.0f, 4.0f);
    sky.at(2, 0) = glm::vec3(5.0f, 6.0f, std::numeric_limits<float>::infinity());
    writeExr(dir.path("sky.exr"), sky);
    WarningCapture capture;
    Image map = loadEnvironmentMap(dir.path("sky.exr"), "label");
    EXPECT_EQ(map.at(0, 0), glm::vec3(1.0f, 0.0f, 2.0f));
    EXPECT_EQ(map.at(1, 0), glm::vec3(0.0f, 3.0f, 4.0f));
    EXPECT_EQ(map.at(2, 0), glm::vec3(5.0f, 6.0f, 0.0f));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], dir.path("sky.exr"), "set 3 negative or non-finite values");
}

TEST(Lighting, SceneFilesTakeExrMaps) {
    test::TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Image sky(4, 2);
    for (size_t i = 0; i < sky.pixels.size(); ++i) sky.pixels[i] = glm::vec3(float(i), 0.5f, 0.25f);
    dir.write("maps/bad.exr", "not an EXR");
    writeExr(dir.path("maps/sky.exr"), sky);
    Scene scene =
        loadScene(dir.write("scene.json", R"({"mesh": "tri.obj", "environment": {"map": "maps/sky.exr",
        "intensity": 3, "rotation": 45}})"));
    ASSERT_TRUE(scene.environment.hasMap());
    EXPECT_EQ(scene.environment.map.pixels, sky.pixels);
    EXPECT_EQ(scene.environment.intensity, 3.0f);
    EXPECT_EQ(scene.environment.rotationDegrees, 45.0f);
    // What the EXR reader refuses, the scene file reports with the file's name.
    std::string message = test::errorOf([&] {
        loadScene(dir.write("bad.json", R"({"mesh": "tri.obj", "environment": {"map": "maps/bad.exr"}})"));
    });
    EXPECT_CONTAINS_ALL(message, dir.path("maps/bad.exr"), "not an OpenEXR file");
}

}  // namespace
}  // namespace fp
