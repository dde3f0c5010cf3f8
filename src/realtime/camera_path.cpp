#include "realtime/camera_path.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file.h"
#include "core/text.h"
#include "scene/text_file.h"

namespace fp {

namespace {

constexpr double kMaxTime = 1e9, kMinSpacing = 1e-6;  // seconds

std::string keyName(size_t i) {
    return "keyframes[" + std::to_string(i) + "]";
}

// The velocity (units per second) at key i of `point` (eye or target): the derivative at t[i] of the
// parabola through keys i-1, i, i+1, i.e. the slopes either side weighted by the opposite interval. This
// is the Catmull-Rom spline with the key times as knots (Barry & Goldman 1988, "A recursive evaluation
// algorithm for a class of Catmull-Rom splines", SIGGRAPH); with evenly spaced keys it is the uniform
// spline of Catmull & Rom 1974, (P[i+1] - P[i-1]) / 2h. Time is the spline's parameter so that velocity
// is continuous in seconds even across unevenly spaced keys (a centripetal parameterisation is C1 only
// in its own parameter). End keys are duplicated with the spacing mirrored: (P[1] - P[0]) / 2h there.
glm::dvec3 velocity(const std::vector<CameraKeyframe>& keys, size_t i, glm::vec3 Camera::*point) {
    size_t last = keys.size() - 1;
    glm::dvec3 p(keys[i].camera.*point), slopeBefore(0.0), slopeAfter(0.0);
    double hBefore = 0.0, hAfter = 0.0;
    if (i > 0) {
        hBefore = keys[i].time - keys[i - 1].time;
        slopeBefore = (p - glm::dvec3(keys[i - 1].camera.*point)) / hBefore;
    }
    if (i < last) {
        hAfter = keys[i + 1].time - keys[i].time;
        slopeAfter = (glm::dvec3(keys[i + 1].camera.*point) - p) / hAfter;
    }
    if (i == 0) hBefore = hAfter;  // the duplicated end point (slope 0)
    if (i == last) hAfter = hBefore;
    return (slopeBefore * hAfter + slopeAfter * hBefore) / (hBefore + hAfter);
}

// Cubic Hermite interpolation over one segment of length h seconds, s in [0, 1); exact at s = 0.
glm::dvec3 hermite(glm::dvec3 p0, glm::dvec3 v0, glm::dvec3 p1, glm::dvec3 v1, double h, double s) {
    double u = 1.0 - s;
    return (1.0 + 2.0 * s) * u * u * p0 + s * u * u * h * v0 + s * s * (3.0 - 2.0 * s) * p1 -
           s * s * u * h * v1;
}

// Eye or target at `s` in segment i.
glm::vec3 spline(const std::vector<CameraKeyframe>& keys, size_t i, double s, glm::vec3 Camera::*point) {
    glm::dvec3 p0(keys[i].camera.*point), p1(keys[i + 1].camera.*point);
    double h = keys[i + 1].time - keys[i].time;
    return glm::vec3(hermite(p0, velocity(keys, i, point), p1, velocity(keys, i + 1, point), h, s));
}

Camera interpolate(const std::vector<CameraKeyframe>& keys, double seconds) {
    if (!(seconds > keys.front().time)) return keys.front().camera;  // NaN too
    if (seconds >= keys.back().time) return keys.back().camera;
    // keys[i].time <= seconds < keys[i + 1].time
    auto next = std::upper_bound(keys.begin(), keys.end(), seconds,
                                 [](double t, const CameraKeyframe& key) { return t < key.time; });
    size_t i = static_cast<size_t>(next - keys.begin()) - 1;
    const Camera &a = keys[i].camera, &b = keys[i + 1].camera;
    double s = (seconds - keys[i].time) / (keys[i + 1].time - keys[i].time);

    Camera c = a;
    c.eye = spline(keys, i, s, &Camera::eye);
    c.target = spline(keys, i, s, &Camera::target);
    c.up = glm::vec3(glm::normalize(glm::mix(glm::dvec3(a.up), glm::dvec3(b.up), s)));
    c.fovY = static_cast<float>(glm::mix(double(a.fovY), double(b.fovY), s));
    c.aperture = static_cast<float>(glm::mix(double(a.aperture), double(b.aperture), s));
    // An unset focus distance follows the target; mixing it with a set one keeps the focus continuous.
    if (a.focusDistance || b.focusDistance)
        c.focusDistance = static_cast<float>(
            glm::mix(double(resolvedFocusDistance(a)), double(resolvedFocusDistance(b)), s));
    return c;
}

Camera orbitAt(const Camera& start, double degreesPerSecond, double seconds, double t) {
    t = t > 0.0 ? std::min(t, seconds) : 0.0;  // NaN: the start
    // Rodrigues' rotation of eye - target about the unit up axis; fmod keeps long orbits precise.
    double angle = glm::radians(std::fmod(degreesPerSecond * t, 360.0));
    glm::dvec3 axis = glm::normalize(glm::dvec3(start.up));
    glm::dvec3 v = glm::dvec3(start.eye) - glm::dvec3(start.target);
    double cosA = std::cos(angle), sinA = std::sin(angle);
    glm::dvec3 turned = v * cosA + glm::cross(axis, v) * sinA + axis * glm::dot(axis, v) * (1.0 - cosA);
    Camera c = start;
    c.eye = glm::vec3(glm::dvec3(start.target) + turned);
    return c;
}

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace

CameraPath::CameraPath(std::vector<CameraKeyframe> keys) {
    if (keys.empty()) throw Error("a camera path needs at least one keyframe");
    for (size_t i = 0; i < keys.size(); ++i) {
        CameraKeyframe& key = keys[i];
        std::string where = keyName(i);
        // Bounds that keep every slope and product of the spline finite in double.
        if (!(std::abs(key.time) <= kMaxTime))
            throw Error(formatText("%s.time must be a number of seconds within +-%g, got %g", where.c_str(),
                                   kMaxTime, key.time));
        if (i > 0 && !(key.time > keys[i - 1].time))
            throw Error(formatText("%s.time (%g) must be after %s.time (%g): times must increase strictly",
                                   where.c_str(), key.time, keyName(i - 1).c_str(), keys[i - 1].time));
        if (i > 0 && !(key.time - keys[i - 1].time >= kMinSpacing))
            throw Error(formatText("%s.time (%g) must be at least %g s after %s.time (%g)", where.c_str(),
                                   key.time, kMinSpacing, keyName(i - 1).c_str(), keys[i - 1].time));
        validateCamera(key.camera, where);
        // In double: a huge up would overflow its length in float.
        key.camera.up = glm::vec3(glm::normalize(glm::dvec3(key.camera.up)));
        // Opposite ups have no normalised lerp half way.
        if (i > 0 && glm::dot(glm::dvec3(key.camera.up), glm::dvec3(keys[i - 1].camera.up)) < -1.0 + 1e-6)
            throw Error(where + ".up is opposite to " + keyName(i - 1) +
                        ".up: the up between them would be undefined");
    }
    shape_ = std::move(keys);
}

Camera CameraPath::at(double seconds) const {
    return std::visit(
        Overloaded{[&](const std::vector<CameraKeyframe>& keys) { return interpolate(keys, seconds); },
                   [&](const Orbit& o) { return orbitAt(o.start, o.degreesPerSecond, o.seconds, seconds); }},
        shape_);
}

double CameraPath::startTime() const {
    if (const auto* keys = std::get_if<std::vector<CameraKeyframe>>(&shape_)) return keys->front().time;
    return 0.0;
}

double CameraPath::duration() const {
    if (const auto* keys = std::get_if<std::vector<CameraKeyframe>>(&shape_))
        return keys->back().time - keys->front().time;
    return std::get<Orbit>(shape_).seconds;
}

CameraPath orbitPath(const Camera& start, double degreesPerSecond, double seconds) {
    validateCamera(start, "orbit camera");  // also: the eye is off the axis, since up is not the view
    if (!std::isfinite(degreesPerSecond))
        throw Error(
            formatText("orbit: degrees per second must be a finite number, got %g", degreesPerSecond));
    if (!(seconds >= 0.0) || !std::isfinite(seconds))
        throw Error(
            formatText("orbit: its length must be a finite number of seconds, 0 or more, got %g", seconds));
    if (!std::isfinite(degreesPerSecond * seconds))
        throw Error("orbit: degrees per second times seconds must be a finite number of degrees");
    return CameraPath(CameraPath::Orbit{start, degreesPerSecond, seconds});
}

namespace {

using nlohmann::json;

// Reads the file's values; every error names the file and the key path ("keyframes[2].eye").
class Reader {
  public:
    explicit Reader(const std::string& file) : file_(file) {}

    [[noreturn]] void fail(const std::string& message) const { throw Error(file_ + ": " + message); }

    // Unknown keys are errors: a typo ("fovy") would otherwise silently give the default.
    void onlyKeys(const json& object, const std::string& where,
                  std::initializer_list<const char*> known) const {
        for (const auto& item : object.items()) {
            if (std::any_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; }))
                continue;
            std::vector<std::string> names(known.begin(), known.end());
            fail(where + item.key() + ": unknown key (expected " + choiceList(names) + ")");
        }
    }

    double number(const json& value, const std::string& where) const {
        if (!value.is_number()) fail(where + ": expected a number, got " + shown(value));
        double d = value.get<double>();
        if (!std::isfinite(d)) fail(where + ": expected a finite number, got " + shown(value));
        return d;
    }

    // A number that stays finite as a float.
    float real(const json& value, const std::string& where) const {
        double d = number(value, where);
        if (!std::isfinite(static_cast<float>(d)))
            fail(where + ": expected a number within float range, got " + shown(value));
        return static_cast<float>(d);
    }

    glm::vec3 vec3(const json& value, const std::string& where) const {
        if (!value.is_array() || value.size() != 3) fail(where + ": expected 3 numbers, got " + shown(value));
        glm::vec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = real(value[static_cast<size_t>(i)], where + "[" + std::to_string(i) + "]");
        return v;
    }

    static std::string shown(const json& value) {
        std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
        return text.size() > 60 ? text.substr(0, 57) + "..." : text;
    }

  private:
    std::string file_;
};

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string withoutId(const json::exception& e) {
    std::string what = e.what();
    size_t start = what.find("] ");
    return start == std::string::npos ? what : what.substr(start + 2);
}

CameraKeyframe readKeyframe(const json& value, size_t i, float previousFov, const Reader& reader) {
    std::string where = keyName(i);
    if (!value.is_object()) reader.fail(where + ": expected a JSON object, got " + Reader::shown(value));
    reader.onlyKeys(value, where + ".", {"time", "eye", "target", "up", "fov"});
    for (const char* key : {"time", "eye", "target"})
        if (!value.contains(key)) reader.fail(where + ": missing \"" + key + "\"");
    CameraKeyframe k{reader.number(value["time"], where + ".time"), Camera{}};
    k.camera.eye = reader.vec3(value["eye"], where + ".eye");
    k.camera.target = reader.vec3(value["target"], where + ".target");
    k.camera.up =
        value.contains("up") ? reader.vec3(value["up"], where + ".up") : glm::vec3(0.0f, 1.0f, 0.0f);
    k.camera.fovY = value.contains("fov") ? reader.real(value["fov"], where + ".fov") : previousFov;
    return k;
}

}  // namespace

CameraPath readCameraPath(const std::string& path) {
    std::string bytes = readFileBytes(path);
    std::string_view text = requireText(bytes, path);
    json root;
    try {
        root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/true,
                           /*ignore_comments=*/true);
    } catch (const json::parse_error& e) {
        throw Error(path + ": invalid JSON: " + withoutId(e) + " (byte " + std::to_string(e.byte) + ")");
    } catch (const json::exception& e) {
        throw Error(path + ": invalid JSON: " + withoutId(e));  // e.g. 1e999, refused without a position
    }
    Reader reader(path);
    if (!root.is_object()) reader.fail("expected a JSON object at the top level, got " + Reader::shown(root));
    reader.onlyKeys(root, "", {"keyframes"});
    if (!root.contains("keyframes")) reader.fail("missing \"keyframes\"");
    const json& list = root["keyframes"];
    if (!list.is_array())
        reader.fail("keyframes: expected an array of keyframes, got " + Reader::shown(list));
    if (list.empty()) reader.fail("keyframes: expected at least 1 keyframe, got none");
    std::vector<CameraKeyframe> keys;
    float fov = Camera{}.fovY;
    for (size_t i = 0; i < list.size(); ++i) {
        keys.push_back(readKeyframe(list[i], i, fov, reader));
        fov = keys.back().camera.fovY;
    }
    try {
        return CameraPath(std::move(keys));
    } catch (const Error& e) {
        reader.fail(e.what());
    }
}

}  // namespace fp
