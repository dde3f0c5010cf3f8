#include "viewer/camera_input.h"

#include <algorithm>

namespace fp {

void CameraInput::setFlying(bool flying) {
    flying_ = flying;
    drag_ = Drag::None;
    haveCursor_ = false;  // capturing or releasing the cursor moves it: no motion from that
}

void CameraInput::update(const InputFrame& input, CameraController& camera) {
    glm::dvec2 delta = haveCursor_ ? input.cursor - lastCursor_ : glm::dvec2(0.0);
    lastCursor_ = input.cursor;
    haveCursor_ = true;
    focusClick_.reset();
    double height = std::max(input.windowSize.y, 1);
    double lookPerPixel = glm::radians(double(camera.camera().fovY)) / height;

    if (flying_) {
        drag_ = Drag::None;
        camera.look(float(delta.x * lookPerPixel), float(-delta.y * lookPerPixel));
    } else {
        bool held[] = {false, input.left, input.left || input.middle, input.right};  // by Drag
        if (!held[int(drag_)]) drag_ = Drag::None;
        // A drag starts only with a press outside the panel, and then owns the mouse until released,
        // even over the panel.
        if (drag_ == Drag::None && !input.uiWantsMouse) {
            if (input.left && !wasLeft_ && input.ctrl)
                focusClick_ = input.cursor;  // a click, not a drag
            else if (input.left && !wasLeft_)
                drag_ = input.shift ? Drag::Pan : Drag::Orbit;
            else if (input.middle && !wasMiddle_)
                drag_ = Drag::Pan;
            else if (input.right && !wasRight_)
                drag_ = Drag::Look;
            if (drag_ != Drag::None) delta = glm::dvec2(0.0);  // the motion before the press is not a drag
        }
        // Screen y grows downward; the controller's arguments describe the camera's motion, so a scene
        // that follows the mouse needs the camera to move the other way (camera_controller.h).
        double orbitPerPixel = kOrbitPerHeight / height;
        switch (drag_) {
            case Drag::Orbit:
                camera.orbit(float(-delta.x * orbitPerPixel), float(delta.y * orbitPerPixel));
                break;
            case Drag::Pan:
                camera.pan(float(-delta.x / height), float(delta.y / height));
                break;
            case Drag::Look:
                camera.look(float(delta.x * lookPerPixel), float(-delta.y * lookPerPixel));
                break;
            case Drag::None:
                break;
        }
    }
    wasLeft_ = input.left;
    wasMiddle_ = input.middle;
    wasRight_ = input.right;

    if (input.scroll != 0.0 && !input.uiWantsMouse) camera.dolly(float(input.scroll * kDollyPerNotch));

    if (flying_ && !input.uiWantsKeyboard) {
        glm::vec3 direction(float(input.strafeRight) - float(input.strafeLeft),
                            float(input.up) - float(input.down), float(input.forward) - float(input.back));
        if (direction != glm::vec3(0.0f))
            camera.fly(direction * camera.suggestedFlySpeed() * float(input.dt));
    }
}

}  // namespace fp
