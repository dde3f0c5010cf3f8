#pragma once
// The interactive camera of the desktop viewer: orbit, pan, dolly, fly, mouse look and reset, as plain
// math over fp::Camera. Nothing here knows about OpenGL or windows, so every motion is unit-tested; the
// viewer turns mouse and key events into these calls and restarts accumulation when version() changes.
//
// Camera basis, exactly as the renderer builds it (src/render/renderer.cpp):
//     forward = normalize(target - eye)
//     right   = normalize(cross(forward, up))
//     imageUp = cross(right, forward)
// `up` is world up: it stays equal to the home camera's up through every call, so the horizon stays
// level. Elevation below means the angle between a direction and the plane perpendicular to world up.
//
// Sign conventions: every argument describes the motion of the CAMERA, never of the scene. A caller that
// wants the scene to follow the mouse ("grab" feel) negates the mouse deltas itself.
//     orbit(yaw, pitch): yaw > 0 moves the eye toward the camera's right around the target (a right-handed
//                        turn about world up); pitch > 0 raises the eye, so the camera looks down more.
//     pan(dx, dy):       dx > 0 moves the camera along `right` (the scene slides left on screen);
//                        dy > 0 moves it along `imageUp` (the scene slides down on screen).
//     dolly(amount):     amount > 0 moves the eye toward the target (zoom in); CameraInput
//                        maps one wheel notch to kDollyPerNotch (camera_input.h).
//     fly(v):            v = (along right, along imageUp, along forward) in world units.
//     look(yaw, pitch):  yaw > 0 turns the view to the right; pitch > 0 tilts it up.
// Screen coordinates usually grow downward, so a viewer passes e.g. pan(-dxPixels / height,
// +dyPixels / height) to make the scene follow a drag.
//
// Robustness: a call with any NaN or infinite argument is ignored. The state is kept in double and
// rounded to float only for camera(); a call whose result the renderer could not use (non-finite
// numbers, eye on the target, view parallel to up) is ignored rather than half-applied. Limits (pitch,
// distance, field of view) only ever stop a motion: they never push the camera back, so a home camera
// that lies outside them is reproduced exactly and can still move back inside.
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

class CameraController {
  public:
    // Vertical field of view accepted by setFov(), in degrees.
    static constexpr float kMinFovDegrees = 1.0f;
    static constexpr float kMaxFovDegrees = 170.0f;
    // Largest elevation of the view direction reached by orbit() and look(): 89 degrees keeps the view at
    // least one degree away from world up, where the basis (cross(forward, up)) would degenerate.
    static constexpr double kMaxElevationDegrees = 89.0;
    // dolly() keeps the eye-target distance within these multiples of the home distance; the lower bound is
    // also raised where float coordinates are large, so the rounded eye never lands on the target.
    static constexpr double kMinDistanceRatio = 1e-4;
    static constexpr double kMaxDistanceRatio = 1e4;

    // `home` is the scene's camera; reset() returns to it. A home camera that cannot form an image
    // (non-finite values, eye == target, up zero or parallel to the view) is repaired first: bad numbers
    // get Camera{}'s defaults, a missing view direction becomes horizontal, a view parallel to up is
    // tilted to the elevation limit.
    explicit CameraController(const Camera& home);

    const Camera& camera() const { return camera_; }
    // The (repaired) home camera.
    const Camera& home() const { return home_; }
    void reset();

    // Turns the eye about the target (radians; conventions above). The target and the eye-target distance
    // stay fixed; the elevation is clamped to +-kMaxElevationDegrees.
    void orbit(float yaw, float pitch);
    // Moves eye and target together in the image plane. dx, dy are fractions of the viewport height: a
    // drag across the full height moves the scene point at the target distance by exactly the visible
    // height there, 2 * distance * tan(fovY / 2). Moves that would carry the target much farther from the
    // origin than float precision allows at this distance are ignored.
    void pan(float dx, float dy);
    // Scales the eye-target distance by exp(-amount), clamped to the distance limits (never reaching or
    // passing the target).
    void dolly(float amount);
    // Moves eye and target together by moveRightUpForward along (right, imageUp, forward) in world units;
    // the caller scales by speed * dt. Same far-from-origin guard as pan().
    void fly(const glm::vec3& moveRightUpForward);
    // Mouse look: turns the view direction about the eye (radians; conventions above), keeping the eye and
    // the eye-target distance; the elevation is clamped as in orbit().
    void look(float yaw, float pitch);
    // Vertical field of view in degrees, clamped to [kMinFovDegrees, kMaxFovDegrees].
    void setFov(float degrees);
    // The thin lens (Camera::aperture, Camera::focusDistance): the lens diameter in scene units (negative
    // values become 0, a pinhole), and the distance to the plane in focus (unset: the target's distance,
    // which then follows orbit and dolly); a focus distance that is not a finite number above 0 is ignored.
    void setAperture(float aperture);
    void setFocusDistance(std::optional<float> distance);

    // Increases by one each time camera() changes and only then: a call that leaves camera() exactly as it
    // was (zero motions, an ignored call, a motion stopped at a limit) keeps it.
    uint64_t version() const { return version_; }
    // A comfortable fly speed in world units per second: a quarter of the eye-target distance.
    float suggestedFlySpeed() const;

  private:
    struct State {
        glm::dvec3 eye{0.0};
        glm::dvec3 target{0.0};
        float fovY = 40.0f;
        float aperture = 0.0f;
        std::optional<float> focusDistance;
    };

    // Adopts `next` if the renderer can use it; bumps the version if camera() changes. False if ignored.
    bool commit(const State& next);
    void translate(const glm::dvec3& delta);
    double distance() const;

    Camera home_;
    State homeState_;
    glm::dvec3 up_{0.0, 1.0, 0.0};  // world up, unit length
    double homeDistance_ = 1.0;
    State state_;
    Camera camera_;
    uint64_t version_ = 0;
};

}  // namespace fp
