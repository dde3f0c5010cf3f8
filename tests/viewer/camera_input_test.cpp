// Mouse and keys -> camera: the scene follows a drag, and the panel keeps the input it owns.
#include "viewer/camera_input.h"

#include <gtest/gtest.h>

namespace fp {
namespace {

Camera homeCamera() {
    Camera c;
    c.eye = {0.0f, 0.0f, -10.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    c.fovY = 40.0f;
    return c;
}

struct Basis {
    glm::vec3 forward, right, up;
};
Basis basisOf(const Camera& c) {
    glm::vec3 f = glm::normalize(c.target - c.eye);
    glm::vec3 r = glm::normalize(glm::cross(f, c.up));
    return {f, r, glm::cross(r, f)};
}

class CameraInputTest : public ::testing::Test {
  protected:
    CameraInputTest() : camera(homeCamera()) { frame.windowSize = {800, 600}; }
    // Presses at `from`, moves to `to` over one frame, releases.
    void drag(glm::dvec2 from, glm::dvec2 to, bool InputFrame::*button, bool shift = false) {
        InputFrame f = frame;
        f.cursor = from;
        input.update(f, camera);  // the cursor is known before the press
        f.*button = true;
        f.shift = shift;
        input.update(f, camera);
        f.cursor = to;
        input.update(f, camera);
        f.*button = false;
        input.update(f, camera);
    }
    CameraController camera;
    CameraInput input;
    InputFrame frame;
};

TEST_F(CameraInputTest, LeftDragOrbitsSoTheSceneFollowsTheMouse) {
    Camera before = camera.camera();
    Basis b = basisOf(before);
    drag({400, 300}, {500, 300}, &InputFrame::left);
    Camera after = camera.camera();
    // Dragging right turns the scene to the right: the eye moves to the camera's left around the target.
    EXPECT_LT(glm::dot(after.eye - before.eye, b.right), 0.0f);
    EXPECT_EQ(after.target, before.target);
    EXPECT_NEAR(glm::length(after.eye - after.target), 10.0f, 1e-3f);

    before = camera.camera();
    b = basisOf(before);
    drag({400, 300}, {400, 400}, &InputFrame::left);
    // Dragging down tips the scene's top toward the viewer: the eye rises.
    EXPECT_GT(glm::dot(camera.camera().eye - before.eye, b.up), 0.0f);
}

TEST_F(CameraInputTest, MiddleAndShiftLeftDragPan) {
    for (bool shift : {false, true}) {
        CameraController c(homeCamera());
        camera = c;
        Camera before = camera.camera();
        Basis b = basisOf(before);
        drag({400, 300}, {460, 360}, shift ? &InputFrame::left : &InputFrame::middle, shift);
        Camera after = camera.camera();
        glm::vec3 moved = after.eye - before.eye;
        EXPECT_EQ(after.target - before.target, moved) << "eye and target move together";
        // The scene follows the mouse right and down: the camera moves left and up.
        EXPECT_LT(glm::dot(moved, b.right), 0.0f);
        EXPECT_GT(glm::dot(moved, b.up), 0.0f);
        // A drag of 60 pixels of a 600-pixel height moves the target plane by a tenth of its visible height.
        float visible = 2.0f * 10.0f * std::tan(glm::radians(20.0f));
        EXPECT_NEAR(glm::dot(moved, b.right), -0.1f * visible, 1e-3f);
    }
}

TEST_F(CameraInputTest, RightDragLooksTheWayTheMouseGoes) {
    Camera before = camera.camera();
    Basis b = basisOf(before);
    drag({400, 300}, {420, 280}, &InputFrame::right);
    Camera after = camera.camera();
    EXPECT_EQ(after.eye, before.eye);
    glm::vec3 forward = basisOf(after).forward;
    EXPECT_GT(glm::dot(forward, b.right), 0.0f);  // turned right
    EXPECT_GT(glm::dot(forward, b.up), 0.0f);     // tilted up (the mouse went up the screen)
}

TEST_F(CameraInputTest, WheelDollies) {
    InputFrame f = frame;
    f.scroll = 1.0;
    input.update(f, camera);
    float distance = glm::length(camera.camera().eye - camera.camera().target);
    EXPECT_NEAR(distance, 10.0f * std::exp(-float(CameraInput::kDollyPerNotch)), 1e-4f);
    f.scroll = -1.0;
    input.update(f, camera);
    EXPECT_NEAR(glm::length(camera.camera().eye - camera.camera().target), 10.0f, 1e-4f);
}

TEST_F(CameraInputTest, ThePanelKeepsWhatStartsOverIt) {
    InputFrame f = frame;
    f.uiWantsMouse = true;
    f.scroll = 1.0;
    input.update(f, camera);
    f.scroll = 0.0;
    f.left = true;  // pressed on the panel
    input.update(f, camera);
    f.uiWantsMouse = false;  // ... and dragged out of it
    f.cursor = {300, 200};
    input.update(f, camera);
    EXPECT_EQ(input.drag(), CameraInput::Drag::None);
    EXPECT_EQ(camera.version(), 0u) << "no camera change";

    // A drag that starts outside continues over the panel.
    f.left = false;
    input.update(f, camera);
    f.left = true;
    input.update(f, camera);
    EXPECT_EQ(input.drag(), CameraInput::Drag::Orbit);
    f.uiWantsMouse = true;
    f.cursor = {350, 200};
    input.update(f, camera);
    EXPECT_EQ(input.drag(), CameraInput::Drag::Orbit);
    EXPECT_GT(camera.version(), 0u);
}

// Ctrl + left click asks to focus where it happened, once, and starts no drag: moving with the button
// held does not orbit. Over the panel it is the panel's; a plain left press still orbits.
TEST_F(CameraInputTest, CtrlClickAsksToFocusAndDoesNotOrbit) {
    InputFrame f = frame;
    f.cursor = {120, 80};
    input.update(f, camera);
    EXPECT_FALSE(input.focusClick());
    f.ctrl = true;
    f.left = true;
    input.update(f, camera);
    ASSERT_TRUE(input.focusClick());
    EXPECT_EQ(*input.focusClick(), glm::dvec2(120, 80));
    EXPECT_EQ(input.drag(), CameraInput::Drag::None);
    f.cursor = {220, 180};  // held and moved: neither another click nor a drag
    input.update(f, camera);
    EXPECT_FALSE(input.focusClick());
    EXPECT_EQ(camera.version(), 0u);
    f.left = false;
    input.update(f, camera);

    f.uiWantsMouse = true;
    f.left = true;
    input.update(f, camera);
    EXPECT_FALSE(input.focusClick()) << "over the panel the click is the panel's";
    f.left = false;
    f.uiWantsMouse = false;
    input.update(f, camera);

    f.ctrl = false;
    f.left = true;
    input.update(f, camera);
    EXPECT_FALSE(input.focusClick());
    EXPECT_EQ(input.drag(), CameraInput::Drag::Orbit);
}

TEST_F(CameraInputTest, PressingIsNotMoving) {
    InputFrame f = frame;
    f.cursor = {100, 100};
    input.update(f, camera);
    f.cursor = {400, 300};  // the cursor moved, then the button went down
    f.left = true;
    input.update(f, camera);
    EXPECT_EQ(camera.version(), 0u);
}

TEST_F(CameraInputTest, FlyModeMovesWithKeysAndLooksWithTheMouse) {
    input.setFlying(true);
    InputFrame f = frame;
    f.dt = 0.5;
    f.forward = true;
    float speed = camera.suggestedFlySpeed();
    Camera before = camera.camera();
    input.update(f, camera);
    glm::vec3 moved = camera.camera().eye - before.eye;
    EXPECT_NEAR(glm::dot(moved, basisOf(before).forward), 0.5f * speed, 1e-3f);

    f.forward = false;
    f.up = true;  // E
    before = camera.camera();
    input.update(f, camera);
    EXPECT_NEAR(glm::dot(camera.camera().eye - before.eye, basisOf(before).up), 0.5f * speed, 1e-3f);

    // Without a button, mouse motion looks around.
    f.up = false;
    before = camera.camera();
    f.cursor += glm::dvec2(50, 0);
    input.update(f, camera);
    EXPECT_EQ(camera.camera().eye, before.eye);
    EXPECT_GT(glm::dot(basisOf(camera.camera()).forward, basisOf(before).right), 0.0f);

    // Keys typed into the panel do not fly.
    f.uiWantsKeyboard = true;
    f.forward = true;
    before = camera.camera();
    input.update(f, camera);
    EXPECT_EQ(camera.camera().eye, before.eye);
}

TEST_F(CameraInputTest, KeysDoNothingOutsideFlyMode) {
    InputFrame f = frame;
    f.dt = 0.5;
    f.forward = f.strafeLeft = f.up = true;
    input.update(f, camera);
    EXPECT_EQ(camera.version(), 0u);
}

}  // namespace
}  // namespace fp
