#pragma once
// Mouse and keyboard -> CameraController. The window code samples the input devices into an
// InputFrame; this class decides what each drag, key and wheel notch does to the camera, so the whole
// mapping (and its signs) is testable without a window.
//
//   left drag            orbit about the target; the scene follows the mouse
//   middle / shift+left  pan; the scene follows the mouse
//   right drag           mouse look
//   wheel                dolly toward / away from the target
//   ctrl + left click    focus: reported as focusClick() for the viewer to measure the depth there
//   fly mode             WASD move, Q/E down/up, the mouse looks (the window captures the cursor)
#include <optional>

#include <glm/glm.hpp>

#include "viewer/camera_controller.h"

namespace fp {

struct InputFrame {
    glm::dvec2 cursor{0.0};  // window coordinates, y down
    bool left = false, middle = false, right = false, shift = false, ctrl = false;
    // Fly keys held: W, S, A, D, Q (down), E (up).
    bool forward = false, back = false, strafeLeft = false, strafeRight = false, down = false, up = false;
    double scroll = 0.0;           // wheel notches since the last frame, > 0 away from the user
    bool uiWantsMouse = false;     // the cursor is over the panel: a new drag belongs to it
    bool uiWantsKeyboard = false;  // a text field has focus
    double dt = 0.0;               // seconds since the last frame
    glm::ivec2 windowSize{1};      // in cursor coordinates
};

class CameraInput {
  public:
    enum class Drag { None, Orbit, Pan, Look };

    // Radians per pixel are these divided by the window height: a drag over the full height orbits by
    // half a turn, and looks by one field of view.
    static constexpr double kOrbitPerHeight = 3.14159265358979;
    // dolly() scales the distance by exp(-amount): one notch moves about 18 % closer.
    static constexpr double kDollyPerNotch = 0.2;

    void update(const InputFrame& input, CameraController& camera);

    // Where a ctrl + left press outside the panel happened this update (window coordinates, y down): a
    // click to focus there, which starts no drag. Empty in every other update.
    const std::optional<glm::dvec2>& focusClick() const { return focusClick_; }

    bool flying() const { return flying_; }
    void setFlying(bool flying);
    Drag drag() const { return drag_; }

  private:
    bool flying_ = false;
    Drag drag_ = Drag::None;
    bool haveCursor_ = false;
    glm::dvec2 lastCursor_{0.0};
    bool wasLeft_ = false, wasMiddle_ = false, wasRight_ = false;  // buttons last frame, to see presses
    std::optional<glm::dvec2> focusClick_;
};

}  // namespace fp
