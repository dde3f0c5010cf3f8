#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace fp {
namespace {

// Coordinates stay below this so that float differences and squared lengths (as the renderer computes
// them) cannot overflow.
constexpr double kMaxCoordinate = 1e18;
// Float keeps about 7 digits: an eye-target distance below this fraction of the target's coordinates would
// leave the view direction coarsely quantised (or the eye rounded onto the target).
constexpr double kPrecision = 1e-4;
// Pitch requests smaller than this are treated as zero, so that a recomputed elevation that sits a few
// ulps inside the clamp does not count as room to move.
constexpr double kNegligibleAngle = 1e-12;

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double maxAbs(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Moves from `current` toward `proposed`, stopping at the limit in the direction of travel. A limit never
// pulls the value back: if `current` is already beyond it, the value stays where it is.
double clampToward(double current, double proposed, double lo, double hi) {
    if (proposed > current) return std::min(proposed, std::max(current, hi));
    if (proposed < current) return std::max(proposed, std::min(current, lo));
    return current;  // equal, or proposed is NaN
}

// Whether the renderer can build its basis from `c` without NaN, checked the way it computes it (in float).
bool usable(const Camera& c) {
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !std::isfinite(c.fovY)) return false;
    if (!(c.fovY > 0.0f && c.fovY < 180.0f)) return false;
    if (!(c.aperture >= 0.0f && std::isfinite(c.aperture))) return false;
    if (c.focusDistance && !(*c.focusDistance > 0.0f && std::isfinite(*c.focusDistance))) return false;
    if (!(maxAbs(c.eye) <= kMaxCoordinate && maxAbs(c.target) <= kMaxCoordinate)) return false;
    glm::vec3 view = c.target - c.eye;
    float viewLength = glm::length(view);
    float upLength = glm::length(c.up);
    if (!(viewLength > 0.0f && std::isfinite(viewLength)) || !(upLength > 0.0f && std::isfinite(upLength)))
        return false;
    glm::vec3 forward = view / viewLength;
    glm::vec3 cross = glm::cross(forward, c.up);
    float sine = glm::length(cross) / upLength;
    // The same threshold as validateCamera(), so every camera we publish also passes the CLI's checks.
    return sine > 1e-6f && std::isfinite(sine);
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovY == b.fovY &&
           a.aperture == b.aperture && a.focusDistance == b.focusDistance;
}

// A unit vector perpendicular to the unit vector `up`: +z for up = +y, as Camera{} looks.
glm::dvec3 perpendicular(const glm::dvec3& up) {
    glm::dvec3 a = glm::abs(up);
    glm::dvec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1, 0, 0)
                      : (a.y <= a.z)             ? glm::dvec3(0, 1, 0)
                                                 : glm::dvec3(0, 0, 1);
    return glm::normalize(glm::cross(axis, up));
}

// Repairs what would stop the home camera from forming an image, leaving a usable camera untouched so
// that reset() reproduces it bit for bit.
Camera repairHome(Camera c) {
    const Camera defaults;
    if (!(c.aperture >= 0.0f && std::isfinite(c.aperture))) c.aperture = defaults.aperture;
    if (c.focusDistance && !(*c.focusDistance > 0.0f && std::isfinite(*c.focusDistance)))
        c.focusDistance = defaults.focusDistance;
    if (!std::isfinite(c.fovY))
        c.fovY = defaults.fovY;
    else if (!(c.fovY > 0.0f && c.fovY < 180.0f))
        c.fovY = std::clamp(c.fovY, CameraController::kMinFovDegrees, CameraController::kMaxFovDegrees);
    float upLength = finite(c.up) ? glm::length(c.up) : 0.0f;
    if (!(upLength >= 1e-18f && upLength <= 1e18f)) c.up = defaults.up;
    if (!finite(c.target) || !(maxAbs(c.target) <= 0.5 * kMaxCoordinate)) c.target = defaults.target;
    if (!finite(c.eye) || !(maxAbs(c.eye) <= 0.5 * kMaxCoordinate)) c.eye = c.target;
    if (usable(c)) return c;

    glm::dvec3 up = glm::normalize(glm::dvec3(c.up));
    glm::dvec3 target(c.target);
    glm::dvec3 offset = glm::dvec3(c.eye) - target;  // from the target to the eye
    double distance = glm::length(offset);
    double minDistance = std::max(1e-6, 2.0 * kPrecision * maxAbs(target));
    double height = glm::dot(offset, up);
    glm::dvec3 horizontal = offset - height * up;
    double horizontalLength = glm::length(horizontal);
    glm::dvec3 direction;
    if (!(distance > 0.0)) {
        // No view direction at all: look horizontally, as Camera{} does.
        direction = perpendicular(up);
    } else if (horizontalLength > 1e-3 * distance) {
        direction = offset / distance;  // only the distance was the problem
    } else {
        // Looking along up: tilt to the elevation limit on the side the eye was.
        double limit = glm::radians(CameraController::kMaxElevationDegrees);
        glm::dvec3 side = horizontalLength > 0.0 ? horizontal / horizontalLength : perpendicular(up);
        direction = std::cos(limit) * side + std::copysign(std::sin(limit), height) * up;
    }
    if (!(distance >= minDistance)) distance = std::max(1.0, minDistance);
    c.eye = glm::vec3(target + distance * direction);
    if (usable(c)) return c;
    return defaults;
}

// Turns `d` about the unit axis `up` by `yaw` (right-handed) and changes its elevation by `pitch`, clamped
// to the elevation limit, keeping its length. Returns false (leaving `d` alone) when nothing would change.
bool turn(glm::dvec3& d, const glm::dvec3& up, double yaw, double pitch) {
    double height = glm::dot(d, up);
    glm::dvec3 horizontal = d - height * up;
    double horizontalLength = glm::length(horizontal);
    double length = glm::length(d);
    if (!(horizontalLength > 0.0) || !(length > 0.0)) return false;  // no azimuth to turn about

    double limit = glm::radians(CameraController::kMaxElevationDegrees);
    double elevation = std::atan2(height, horizontalLength);
    double newElevation = clampToward(elevation, elevation + pitch, -limit, limit);
    bool pitches = std::abs(newElevation - elevation) > kNegligibleAngle;
    if (yaw == 0.0 && !pitches) return false;

    // Reduce first: sin and cos of 1e6 rad are exact enough in double, but this keeps them tidy.
    double angle = std::remainder(yaw, 2.0 * glm::pi<double>());
    glm::dvec3 azimuth = horizontal / horizontalLength;
    glm::dvec3 turned = azimuth * std::cos(angle) + glm::cross(up, azimuth) * std::sin(angle);
    if (pitches)
        d = length * (std::cos(newElevation) * turned + std::sin(newElevation) * up);
    else  // yaw only: keep the height and horizontal length as they were, so the elevation does not drift
        d = horizontalLength * turned + height * up;
    return true;
}

}  // namespace

CameraController::CameraController(const Camera& home) : home_(repairHome(home)) {
    up_ = glm::normalize(glm::dvec3(home_.up));
    homeState_.eye = glm::dvec3(home_.eye);
    homeState_.target = glm::dvec3(home_.target);
    homeState_.fovY = home_.fovY;
    homeState_.aperture = home_.aperture;
    homeState_.focusDistance = home_.focusDistance;
    homeDistance_ = glm::length(homeState_.eye - homeState_.target);
    state_ = homeState_;
    camera_ = home_;
}

void CameraController::reset() {
    commit(homeState_);
}

double CameraController::distance() const {
    return glm::length(state_.eye - state_.target);
}

bool CameraController::commit(const State& next) {
    Camera c = home_;
    c.eye = glm::vec3(next.eye);
    c.target = glm::vec3(next.target);
    c.fovY = next.fovY;
    c.aperture = next.aperture;
    c.focusDistance = next.focusDistance;
    if (!usable(c)) return false;
    // The double state moves even when the rounded camera does not, so that many tiny steps add up.
    state_ = next;
    if (!sameCamera(c, camera_)) {
        camera_ = c;
        ++version_;
    }
    return true;
}

void CameraController::orbit(float yaw, float pitch) {
    if (!std::isfinite(yaw) || !std::isfinite(pitch)) return;
    glm::dvec3 offset = state_.eye - state_.target;
    if (!turn(offset, up_, yaw, pitch)) return;
    State next = state_;
    next.eye = state_.target + offset;
    commit(next);
}

void CameraController::look(float yaw, float pitch) {
    if (!std::isfinite(yaw) || !std::isfinite(pitch)) return;
    glm::dvec3 view = state_.target - state_.eye;
    // A right-handed turn about up swings forward toward -right, so turning right is a negative turn.
    if (!turn(view, up_, -double(yaw), pitch)) return;
    State next = state_;
    next.target = state_.eye + view;
    commit(next);
}

void CameraController::translate(const glm::dvec3& delta) {
    if (!finite(delta) || delta == glm::dvec3(0.0)) return;
    State next = state_;
    next.eye += delta;
    next.target += delta;
    // Float resolution at the target must stay well below the eye-target distance; moving outward beyond
    // that radius is refused (moving back toward the origin is always allowed).
    double radius = std::max(maxAbs(state_.target), distance() / kPrecision);
    if (!(maxAbs(next.target) <= radius)) return;
    commit(next);
}

void CameraController::pan(float dx, float dy) {
    if (!std::isfinite(dx) || !std::isfinite(dy) || (dx == 0.0f && dy == 0.0f)) return;
    glm::dvec3 forward = glm::normalize(state_.target - state_.eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, up_));
    glm::dvec3 imageUp = glm::cross(right, forward);
    // The visible height at the target distance: a full-height drag moves the camera by exactly that.
    double height = 2.0 * distance() * std::tan(0.5 * glm::radians(double(state_.fovY)));
    translate((double(dx) * right + double(dy) * imageUp) * height);
}

void CameraController::fly(const glm::vec3& moveRightUpForward) {
    if (!finite(moveRightUpForward)) return;
    glm::dvec3 m(moveRightUpForward);
    glm::dvec3 forward = glm::normalize(state_.target - state_.eye);
    glm::dvec3 right = glm::normalize(glm::cross(forward, up_));
    glm::dvec3 imageUp = glm::cross(right, forward);
    translate(m.x * right + m.y * imageUp + m.z * forward);
}

void CameraController::dolly(float amount) {
    if (!std::isfinite(amount) || amount == 0.0f) return;
    double current = distance();
    // Near large coordinates the floor rises, so the float eye stays clearly apart from the float target.
    double minDistance =
        std::max(kMinDistanceRatio * homeDistance_, 2.0 * kPrecision * maxAbs(state_.target));
    double maxDistance = std::min(kMaxDistanceRatio * homeDistance_, 0.25 * kMaxCoordinate);
    // exp() may overflow to inf or underflow to 0 for huge amounts; clampToward() handles both.
    double wanted = clampToward(current, current * std::exp(-double(amount)), minDistance, maxDistance);
    if (wanted == current) return;
    State next = state_;
    next.eye = state_.target + (state_.eye - state_.target) * (wanted / current);
    commit(next);
}

void CameraController::setFov(float degrees) {
    if (!std::isfinite(degrees)) return;
    State next = state_;
    next.fovY = std::clamp(degrees, kMinFovDegrees, kMaxFovDegrees);
    commit(next);
}

void CameraController::setAperture(float aperture) {
    if (!std::isfinite(aperture)) return;
    State next = state_;
    next.aperture = std::max(aperture, 0.0f);
    commit(next);
}

void CameraController::setFocusDistance(std::optional<float> distance) {
    if (distance && !(*distance > 0.0f && std::isfinite(*distance))) return;
    State next = state_;
    next.focusDistance = distance;
    commit(next);
}

float CameraController::suggestedFlySpeed() const {
    return float(0.25 * distance());
}

}  // namespace fp
