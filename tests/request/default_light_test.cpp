// The default light (request/default_light.h): the studio environment for a scene without light of its
// own, with a note; glowing detail does not count as light, a room's lamp does.
#include <gtest/gtest.h>

#include <string>

#include "request/default_light.h"
#include "scene/lighting.h"
#include "scene/load.h"
#include "scene/scene_test_util.h"
#include "scene/studio_environment.h"

namespace fp {
namespace {

TEST(DefaultLight, AnUnlitSceneGetsTheStudioEnvironmentWithANote) {
    Scene scene = test::unlitTriangle();
    WarningCapture capture;
    EXPECT_TRUE(lightIfUnlit(scene));
    const Environment studio = studioEnvironment();
    EXPECT_EQ(scene.environment.map.pixels, studio.map.pixels);
    EXPECT_EQ(scene.environment.color, glm::vec3(0.0f));
    EXPECT_TRUE(capture.messages().empty()) << "a note, not a warning: " << test::joined(capture);
    ASSERT_EQ(capture.notes().size(), 1u);
    EXPECT_EQ(
        capture.notes()[0],
        "unlit.obj: no light of its own: lit by the studio environment (--environment none keeps it dark)");
    // Now lit: nothing changes, no second note.
    EXPECT_FALSE(lightIfUnlit(scene));
    EXPECT_EQ(capture.notes().size(), 1u);
    // The native reference's choice: the uniform sky.
    Scene native = test::unlitTriangle();
    EXPECT_TRUE(lightIfUnlit(native, DefaultLight::UniformSky));
    EXPECT_EQ(native.environment.color, glm::vec3(1.0f));
    EXPECT_FALSE(native.environment.hasMap());
    EXPECT_NE(capture.notes().back().find("lit by a uniform white sky of radiance 1"), std::string::npos);
}

// Emitters that are glowing detail (request/own_light.h) get the studio light too, and the note says why;
// a lamp that lights its room is left alone.
TEST(DefaultLight, GlowingDetailIsNotLightButALampInARoomIs) {
    Scene scene = test::unlitTriangle();
    Material glow;
    glow.emission = glm::vec3(1.0f);
    scene.materials.push_back(glow);
    Triangle t = scene.triangles[0];
    t.material = 1;
    t.p = {glm::vec3(2, 0, 0), glm::vec3(3, 0, 0), glm::vec3(2, 1, 0)};
    scene.triangles.push_back(t);
    ASSERT_TRUE(hasLight(scene));
    WarningCapture capture;
    EXPECT_TRUE(lightIfUnlit(scene));
    EXPECT_TRUE(scene.environment.hasMap());
    ASSERT_EQ(capture.notes().size(), 1u);
    EXPECT_CONTAINS_ALL(capture.notes()[0],
                        "unlit.obj: its emitters are glowing detail, not lighting (0.00% of",
                        "lit by the studio environment");
    Scene cornell = loadScene(std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.obj");
    EXPECT_FALSE(lightIfUnlit(cornell));
    EXPECT_TRUE(cornell.environment.isBlack());
    EXPECT_EQ(capture.notes().size(), 1u);
}

TEST(DefaultLight, ALitSceneKeepsItsEnvironment) {
    Scene scene = test::unlitTriangle();
    scene.environment.color = glm::vec3(0.25f);
    WarningCapture capture;
    EXPECT_FALSE(lightIfUnlit(scene));
    EXPECT_EQ(scene.environment.color, glm::vec3(0.25f));
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

TEST(DefaultLight, StrictModeAcceptsTheDefaultLight) {
    // The studio light is the documented default (as the default camera is), not a repair.
    Scene scene = test::unlitTriangle();
    setStrictWarnings(true);
    bool lit = false;
    EXPECT_NO_THROW(lit = lightIfUnlit(scene));
    setStrictWarnings(false);
    EXPECT_TRUE(lit);
    EXPECT_TRUE(scene.environment.hasMap());
}

}  // namespace
}  // namespace fp
