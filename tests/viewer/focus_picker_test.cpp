// Click to focus (viewer/focus_picker.h): the focus distance is the depth along the view direction of
// the surface under the cursor, the distance a thin lens's plane of focus is measured in, not the
// distance along the ray.
#include "viewer/focus_picker.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/procedural.h"

namespace fp {
namespace {

// A wall across the view at z = 10 (10 x 10), and a small card at z = 4 in front of its upper right.
Scene wallAndCard() {
    Scene scene;
    scene.materials.push_back(Material{});
    appendQuad(scene, {-5, -5, 10}, {5, -5, 10}, {5, 5, 10}, {-5, 5, 10}, 0);
    appendQuad(scene, {-1.0f, 0.5f, 4}, {-0.5f, 0.5f, 4}, {-0.5f, 1.0f, 4}, {-1.0f, 1.0f, 4}, 0);
    return scene;
}

Camera lookingAlongZ() {
    Camera c;
    c.eye = {0, 0, 0};
    c.target = {0, 0, 3};  // the target's distance is not the focus the click finds
    c.fovY = 60.0f;
    return c;
}

TEST(FocusPicker, TheDepthAlongTheViewOfTheSurfaceUnderTheCursor) {
    Scene scene = wallAndCard();
    FocusPicker picker(scene, 1);
    Camera c = lookingAlongZ();
    const float aspect = 1.5f, tanHalf = std::tan(glm::radians(30.0f));
    // The centre and an off-centre point of the wall: depth 10 both, though the second ray is longer.
    EXPECT_NEAR(*picker.focusDistanceAt(c, aspect, {0.0f, 0.0f}), 10.0f, 1e-4f);
    EXPECT_NEAR(*picker.focusDistanceAt(c, aspect, {0.3f, -0.6f}), 10.0f, 1e-4f);
    // The card, at x in [-1, -0.5], y in [0.5, 1], depth 4: right = forward x up = -x, so its centre
    // (-0.75, 0.75) is at ndc x = 0.75 / (4 tan aspect), y = 0.75 / (4 tan).
    glm::vec2 card(0.75f / (4.0f * tanHalf * aspect), 0.75f / (4.0f * tanHalf));
    EXPECT_NEAR(*picker.focusDistanceAt(c, aspect, card), 4.0f, 1e-4f);
    // Beside the wall: nothing to focus on.
    EXPECT_FALSE(picker.focusDistanceAt(c, aspect, {0.99f, 0.99f}).has_value());
    // Seen from elsewhere, the depth is along the new view.
    c.eye = {0, 0, -2};
    EXPECT_NEAR(*picker.focusDistanceAt(c, aspect, {0.0f, 0.0f}), 12.0f, 1e-4f);
}

// Instances are where their transforms place them: the wall and the card as one mesh (made at depth 0
// and 6 less), placed 6 further away than the world's copy would be, and nothing else.
TEST(FocusPicker, InstancesAreWhereTheyArePlaced) {
    Scene made = wallAndCard();
    Scene scene;
    scene.materials = made.materials;
    scene.meshes.push_back({"wall and card", made.triangles, {}});
    for (Triangle& t : scene.meshes[0].triangles)
        for (glm::vec3& p : t.p) p.z -= 6.0f;
    glm::mat4 placed(1.0f);
    placed[3] = glm::vec4(0, 0, 12, 1);  // 6 back where they were, and 6 further
    scene.instances.push_back({0, placed});
    FocusPicker picker(scene, 1);
    EXPECT_NEAR(*picker.focusDistanceAt(lookingAlongZ(), 1.5f, {0.0f, 0.0f}), 16.0f, 1e-4f);
}

TEST(FocusPicker, AnEmptySceneHasNothingToFocusOn) {
    Scene scene;
    FocusPicker picker(scene);
    EXPECT_FALSE(picker.focusDistanceAt(lookingAlongZ(), 1.0f, {0.0f, 0.0f}).has_value());
}

TEST(FocusPicker, CursorToNdc) {
    // Window coordinates have y down; normalised device coordinates y up.
    EXPECT_EQ(cursorToNdc({0, 0}, {800, 600}), glm::vec2(-1.0f, 1.0f));
    EXPECT_EQ(cursorToNdc({800, 600}, {800, 600}), glm::vec2(1.0f, -1.0f));
    EXPECT_EQ(cursorToNdc({400, 150}, {800, 600}), glm::vec2(0.0f, 0.5f));
}

}  // namespace
}  // namespace fp
