#pragma once
// Camera paths for `fragpath realtime`: the camera as a function of time, from keyframes (a spline) or
// an orbit about the scene camera's target (exact, no keyframes). No GL here.
//
// A path file is JSON; up and fov are optional (up (0, 1, 0); fov the previous keyframe's, else 40):
//   {"keyframes": [{"time": 0, "eye": [0, 1, -5], "target": [0, 1, 0], "up": [0, 1, 0], "fov": 40},
//                  {"time": 2.5, "eye": [3, 1, -4], "target": [0, 1, 0]}]}
#include <string>
#include <variant>
#include <vector>

#include "scene/scene.h"

namespace fp {

struct CameraKeyframe {
    double time;  // seconds
    Camera camera;
};

class CameraPath {
  public:
    // Throws fp::Error (naming "keyframes[i]...") if `keys` is empty, a time is outside +-1e9 s or less
    // than 1 us after the one before, a camera fails validateCamera, or two consecutive ups are opposite.
    explicit CameraPath(std::vector<CameraKeyframe> keys);

    // The camera at `seconds`, clamped to [startTime(), startTime() + duration()] (NaN: the start).
    // Keyframes: eye and target on a C1 Catmull-Rom spline (camera_path.cpp), fov, aperture and focus
    // distance linear, up a normalised lerp; exactly the keyframe at its time. Between keys the camera
    // is not checked: a path may pass its eye through its target, so callers validate each frame.
    Camera at(double seconds) const;
    double startTime() const;
    double duration() const;

  private:
    struct Orbit {
        Camera start;
        double degreesPerSecond, seconds;
    };
    explicit CameraPath(const Orbit& orbit) : shape_(orbit) {}
    friend CameraPath orbitPath(const Camera& start, double degreesPerSecond, double seconds);

    std::variant<std::vector<CameraKeyframe>, Orbit> shape_;
};

// The orbit's rate unless told otherwise: `fragpath realtime` and the study's practice runs.
constexpr double kDefaultOrbitDegreesPerSecond = 10.0;

// From time 0 to `seconds`: the eye turns about the axis through start.target along start.up (counter-
// clockwise seen from above, i.e. right-handed about up, for degreesPerSecond > 0), keeping its distance
// to the target and its height along up; it starts at start.eye and everything else stays start's.
// Throws fp::Error for an invalid start camera or a rate or length that is not finite (or seconds < 0).
CameraPath orbitPath(const Camera& start, double degreesPerSecond, double seconds);

// A path file (format above). Throws fp::Error naming the file and the key path ("path.json:
// keyframes[2].eye: expected 3 numbers, got [1,2]") for a missing or unreadable file, invalid JSON,
// unknown keys, wrong types, no keyframes and every reason the constructor refuses.
CameraPath readCameraPath(const std::string& path);

}  // namespace fp
