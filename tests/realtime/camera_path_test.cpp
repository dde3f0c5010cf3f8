// Camera paths: the keyframe spline (exact at keys, C1 across them, uniform on a line), the analytic
// orbit, and every way a path file can be wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "realtime/camera_path.h"
#include "scene/scene_test_util.h"

namespace fp {
namespace {

using test::errorOf;

Camera camera(glm::vec3 eye, glm::vec3 target, glm::vec3 up = {0, 1, 0}, float fov = 40.0f) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.up = up;
    c.fovY = fov;
    return c;
}

// Unevenly spaced keys on a curve, so that a spline that ignored the times would show a kink.
std::vector<CameraKeyframe> curvyKeys() {
    return {{0.0, camera({0, 1, -5}, {0, 0, 0}, {0, 1, 0}, 40)},
            {1.0, camera({3, 1, -4}, {0.5f, 0, 0}, {1, 0, 0}, 50)},
            {3.0, camera({4, 2, 0}, {1, 0.5f, 0}, {0, 1, 0}, 30)},
            {3.5, camera({2, 1.5f, 3}, {0.5f, 0, 0.5f}, {0, 1, 0}, 30)},
            {5.0, camera({-1, 1, 4}, {0, 0, 1}, {0, 1, 0}, 60)}};
}

// Bounds of what the eye and target of these paths do, for the tolerances below: measured with steps of
// 1e-3 s, at most 8 units/s and 17 units/s^2 (curvyKeys; 11 on the parabola's), then doubled or more.
constexpr double kMaxSpeed = 20.0;         // units / s
constexpr double kMaxAcceleration = 40.0;  // units / s^2

// How far the difference of two float positions with coordinates up to `coordinate` may be off (half an
// ulp in each of three components of each).
double floatRounding(double coordinate) {
    return std::sqrt(3.0) * coordinate * std::numeric_limits<float>::epsilon();
}

double distance(glm::vec3 a, glm::vec3 b) {
    return glm::length(glm::dvec3(a) - glm::dvec3(b));
}

TEST(CameraPath, InterpolatesKeyframesExactlyAtTheirTimes) {
    std::vector<CameraKeyframe> keys = curvyKeys();
    CameraPath path(keys);
    for (const CameraKeyframe& key : keys) {
        SCOPED_TRACE("t = " + std::to_string(key.time));
        Camera c = path.at(key.time);
        EXPECT_EQ(c.eye, key.camera.eye);
        EXPECT_EQ(c.target, key.camera.target);
        EXPECT_EQ(c.up, key.camera.up);
        EXPECT_EQ(c.fovY, key.camera.fovY);
    }
    // Between keys it is somewhere else.
    EXPECT_GT(distance(path.at(0.5).eye, keys[0].camera.eye), 0.1);
    EXPECT_GT(distance(path.at(0.5).eye, keys[1].camera.eye), 0.1);
}

TEST(CameraPath, MotionAndVelocityAreContinuousAcrossKeys) {
    std::vector<CameraKeyframe> keys = curvyKeys();
    CameraPath path(keys);
    const double d = 1e-3;
    const double rounding = floatRounding(5.0);  // coordinates within +-5
    for (size_t k = 1; k + 1 < keys.size(); ++k) {
        const double t = keys[k].time;
        for (glm::vec3 Camera::*point : {&Camera::eye, &Camera::target}) {
            SCOPED_TRACE("key " + std::to_string(k) + (point == &Camera::eye ? " eye" : " target"));
            glm::dvec3 left(path.at(t - d).*point), here(path.at(t).*point), right(path.at(t + d).*point);
            // Continuous: a step of d moves at most the path's top speed times d.
            EXPECT_LE(glm::length(here - left), kMaxSpeed * d + rounding);
            EXPECT_LE(glm::length(right - here), kMaxSpeed * d + rounding);
            // C1: one-sided differences each miss the velocity by at most d/2 |p''| (Taylor), plus rounding.
            glm::dvec3 vLeft = (here - left) / d, vRight = (right - here) / d;
            EXPECT_LE(glm::length(vRight - vLeft), kMaxAcceleration * d + 2.0 * rounding / d)
                << "left " << vLeft.x << "," << vLeft.y << "," << vLeft.z << " right " << vRight.x << ","
                << vRight.y << "," << vRight.z;
        }
    }
}

// On a parabola p(t) = a + b t + c t^2 sampled at uneven times, the spline's velocity at an interior key
// is the parabola's, b + 2 c t (the tangent is that of the parabola through the key and its neighbours).
TEST(CameraPath, InteriorVelocityIsThatOfTheParabolaThroughThreeKeys) {
    const glm::dvec3 a(1, 2, -3), b(2, -1, 0.5), c(-0.5, 0.25, 1);
    auto parabola = [&](double t) { return a + b * t + c * t * t; };
    std::vector<CameraKeyframe> keys;
    for (double t : {0.0, 0.5, 2.0, 2.25, 4.0})
        keys.push_back({t, camera(glm::vec3(parabola(t)), glm::vec3(parabola(t)) + glm::vec3(0, 0, 1))});
    CameraPath path(keys);
    const double d = 1e-3;
    for (size_t k = 1; k + 1 < keys.size(); ++k) {
        double t = keys[k].time;
        glm::dvec3 central = (glm::dvec3(path.at(t + d).eye) - glm::dvec3(path.at(t - d).eye)) / (2 * d);
        glm::dvec3 exact = b + 2.0 * c * t;
        // The central difference of a C1 piecewise cubic misses p' by d/4 |p''_right - p''_left| <= d/2
        // max|p''|.
        EXPECT_LE(glm::length(central - exact), kMaxAcceleration * d / 2 + floatRounding(16.0) / (2 * d))
            << "t = " << t;
    }
}

TEST(CameraPath, EvenlySpacedKeysOnALineMoveAtConstantSpeed) {
    const glm::vec3 start(1, 0, -2), step(1, 2, -2);  // |step| = 3: 3 units/s with keys 1 s apart
    std::vector<CameraKeyframe> keys;
    for (int i = 0; i <= 4; ++i) keys.push_back({double(i), camera(start + float(i) * step, {0, 0, 5})});
    CameraPath path(keys);
    const double d = 1e-3, tolerance = floatRounding(13.0) / d;  // coordinates within +-13
    // Between the inner keys: 3 units/s throughout, along the line.
    for (double t = 1.0; t <= 3.0 - d; t += 0.05) {
        glm::dvec3 p(path.at(t).eye), q(path.at(t + d).eye);
        EXPECT_NEAR(glm::length(q - p) / d, 3.0, tolerance) << "t = " << t;
        EXPECT_NEAR(glm::length(glm::cross(p - glm::dvec3(start), glm::dvec3(step))), 0.0, 1e-4) << t;
    }
    // The end keys are duplicated, so the path eases in and out: half the speed at its ends (one-sided
    // differences off by d/2 |p''|, which is 6 units/s^2 there: 6 (P1 - P0) / h^2 - (4 v0 + 2 v1) / h).
    EXPECT_NEAR(distance(path.at(d).eye, path.at(0.0).eye) / d, 1.5, 3.0 * d + tolerance);
    EXPECT_NEAR(distance(path.at(4.0).eye, path.at(4.0 - d).eye) / d, 1.5, 3.0 * d + tolerance);
}

TEST(CameraPath, InterpolatesFovLinearlyAndUpByNormalisedLerp) {
    CameraPath path({{2.0, camera({0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 30)},
                     {4.0, camera({0, 0, -5}, {0, 0, 0}, {1, 0, 0}, 60)}});
    EXPECT_FLOAT_EQ(path.at(2.5).fovY, 37.5f);
    EXPECT_FLOAT_EQ(path.at(3.0).fovY, 45.0f);
    glm::vec3 up = path.at(3.0).up;
    EXPECT_NEAR(up.x, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(up.y, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(up.z, 0.0, 1e-6);
    // Keys' ups are normalised.
    CameraPath scaled({{0.0, camera({0, 0, -5}, {0, 0, 0}, {0, 2, 0})}});
    EXPECT_EQ(scaled.at(0.0).up, glm::vec3(0, 1, 0));
}

TEST(CameraPath, ClampsOutsideItsTimeRange) {
    std::vector<CameraKeyframe> keys = curvyKeys();
    for (CameraKeyframe& key : keys) key.time += 10.0;  // 10 s to 15 s
    CameraPath path(keys);
    EXPECT_DOUBLE_EQ(path.startTime(), 10.0);
    EXPECT_DOUBLE_EQ(path.duration(), 5.0);
    const Camera &first = keys.front().camera, &last = keys.back().camera;
    for (double t : {-1e300, -3.0, 0.0, 9.999, -std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN()}) {
        EXPECT_EQ(path.at(t).eye, first.eye) << t;
        EXPECT_EQ(path.at(t).target, first.target) << t;
    }
    for (double t : {15.001, 20.0, 1e300, std::numeric_limits<double>::infinity()}) {
        EXPECT_EQ(path.at(t).eye, last.eye) << t;
        EXPECT_EQ(path.at(t).fovY, last.fovY) << t;
    }
    // A single keyframe is a still.
    CameraPath still({{1.0, first}});
    EXPECT_EQ(still.duration(), 0.0);
    EXPECT_EQ(still.at(1.0).eye, first.eye);
    EXPECT_EQ(still.at(7.0).eye, first.eye);
}

TEST(CameraPath, RefusesKeyframesThatCannotFormAPath) {
    auto reject = [](std::vector<CameraKeyframe> keys) { return errorOf([&] { CameraPath path(keys); }); };
    const Camera ok = camera({0, 0, -5}, {0, 0, 0});
    EXPECT_CONTAINS_ALL(reject({}), "at least one keyframe");
    EXPECT_CONTAINS_ALL(reject({{0.0, ok}, {1.0, ok}, {1.0, ok}}), "keyframes[2].time (1)",
                        "after keyframes[1].time (1)");
    EXPECT_CONTAINS_ALL(reject({{1.0, ok}, {0.5, ok}}), "keyframes[1].time (0.5)", "increase strictly");
    EXPECT_CONTAINS_ALL(reject({{0.0, ok}, {1e-9, ok}}), "keyframes[1].time", "at least 1e-06 s after");
    EXPECT_CONTAINS_ALL(reject({{std::numeric_limits<double>::quiet_NaN(), ok}}), "keyframes[0].time");
    EXPECT_CONTAINS_ALL(reject({{0.0, ok}, {2e9, ok}}), "keyframes[1].time", "within");
    EXPECT_CONTAINS_ALL(reject({{0.0, ok}, {1.0, camera({1, 1, 1}, {1, 1, 1})}}),
                        "keyframes[1].eye and keyframes[1].target are the same point");
    EXPECT_CONTAINS_ALL(reject({{0.0, camera({0, 5, 0}, {0, 0, 0})}}), "keyframes[0].up is parallel");
    EXPECT_CONTAINS_ALL(reject({{0.0, camera({0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 180)}}), "keyframes[0].fov");
    EXPECT_CONTAINS_ALL(reject({{0.0, camera({0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 0)}}), "keyframes[0].fov");
    EXPECT_CONTAINS_ALL(reject({{0.0, ok}, {1.0, camera({0, 0, -5}, {0, 0, 0}, {0, -1, 0})}}),
                        "keyframes[1].up is opposite to keyframes[0].up");
}

// The eye's angle about +y, seen from above, from +z towards +x (right-handed about up).
double azimuthDegrees(glm::vec3 eye, glm::vec3 target) {
    glm::dvec3 v = glm::dvec3(eye) - glm::dvec3(target);
    return glm::degrees(std::atan2(v.x, v.z));
}

TEST(CameraPath, OrbitStartsAtTheEyeAndTurnsByTheRateTimesTime) {
    const glm::vec3 target(1, -1, 2);
    Camera start = camera(target + glm::vec3(0, 3, 4), target, {0, 1, 0}, 35);
    start.aperture = 0.1f;
    CameraPath orbit = orbitPath(start, 90.0, 4.0);
    EXPECT_EQ(orbit.startTime(), 0.0);
    EXPECT_EQ(orbit.duration(), 4.0);
    EXPECT_EQ(orbit.at(0.0).eye, start.eye);
    // By hand: a quarter turn about +y takes +z to +x, a half turn to -z.
    glm::vec3 quarter = orbit.at(1.0).eye - target, half = orbit.at(2.0).eye - target;
    EXPECT_NEAR(quarter.x, 4.0, 1e-5);
    EXPECT_NEAR(quarter.y, 3.0, 1e-5);
    EXPECT_NEAR(quarter.z, 0.0, 1e-5);
    EXPECT_NEAR(half.x, 0.0, 1e-5);
    EXPECT_NEAR(half.z, -4.0, 1e-5);
    for (double t : {0.25, 0.5, 1.0, 1.5, 1.9})
        EXPECT_NEAR(azimuthDegrees(orbit.at(t).eye, target), 90.0 * t, 1e-4);
    // Past the end it stays at 360 degrees, back where it started; the other way for a negative rate.
    EXPECT_NEAR(distance(orbit.at(10.0).eye, start.eye), 0.0, 1e-5);
    CameraPath back = orbitPath(start, -30.0, 3.0);
    EXPECT_NEAR(azimuthDegrees(back.at(1.0).eye, target), -30.0, 1e-4);
    EXPECT_NEAR(azimuthDegrees(back.at(7.0).eye, target), -90.0, 1e-4);
    // Everything but the eye stays.
    Camera c = orbit.at(1.3);
    EXPECT_EQ(c.target, start.target);
    EXPECT_EQ(c.up, start.up);
    EXPECT_EQ(c.fovY, start.fovY);
    EXPECT_EQ(c.aperture, start.aperture);
}

TEST(CameraPath, OrbitKeepsTheDistanceToTheTargetAndTheHeight) {
    // A tilted axis: the height is measured along the start camera's up, through the target.
    const glm::vec3 target(2, 0, -1), up = glm::normalize(glm::vec3(1, 2, 0.5f));
    Camera start = camera(target + glm::vec3(-3, 1, 4), target, up);
    const double height = glm::dot(glm::dvec3(start.eye) - glm::dvec3(target), glm::dvec3(up));
    const double radius = distance(start.eye, target);
    CameraPath orbit = orbitPath(start, 47.0, 20.0);
    glm::vec3 farthest = start.eye;
    for (double t = 0.0; t <= 20.0; t += 0.1) {
        glm::vec3 eye = orbit.at(t).eye;
        EXPECT_NEAR(distance(eye, target), radius, 1e-5) << t;
        EXPECT_NEAR(glm::dot(glm::dvec3(eye) - glm::dvec3(target), glm::dvec3(up)), height, 1e-5) << t;
        if (distance(eye, start.eye) > distance(farthest, start.eye)) farthest = eye;
    }
    // It does go round: the far side of the circle is its diameter away.
    double ring = std::sqrt(radius * radius - height * height);
    EXPECT_NEAR(distance(farthest, start.eye), 2.0 * ring, 0.05);
}

TEST(CameraPath, OrbitRefusesWhatCannotTurn) {
    Camera start = camera({0, 0, -5}, {0, 0, 0});
    EXPECT_CONTAINS_ALL(errorOf([&] { orbitPath(start, std::nan(""), 1.0); }),
                        "degrees per second must be a finite number");
    EXPECT_CONTAINS_ALL(errorOf([&] { orbitPath(start, 10.0, -1.0); }), "seconds");
    EXPECT_CONTAINS_ALL(errorOf([&] { orbitPath(start, 10.0, HUGE_VAL); }), "seconds");
    EXPECT_CONTAINS_ALL(errorOf([&] { orbitPath(start, 1e300, 1e300); }), "finite number of degrees");
    EXPECT_CONTAINS_ALL(errorOf([&] {
                            orbitPath(camera({0, 5, 0}, {0, 0, 0}), 10.0, 1.0);
                        }),
                        "orbit camera.up is parallel");
}

TEST(CameraPathFile, ReadsKeyframesWithDefaults) {
    test::TempDir dir;
    std::string file = dir.write("path.json", R"({"keyframes": [
        {"time": 0, "eye": [0, 1, -5], "target": [0, 1, 0]},
        // comments are allowed, as in scene files
        {"time": 1.5, "eye": [3, 1, -4], "target": [0, 1, 0], "up": [0, 0, 2], "fov": 60},
        {"time": 4, "eye": [5, 1, 0], "target": [0, 1, 0.5]}]})");
    CameraPath path = readCameraPath(file);
    EXPECT_EQ(path.startTime(), 0.0);
    EXPECT_EQ(path.duration(), 4.0);
    Camera a = path.at(0.0), b = path.at(1.5), c = path.at(4.0);
    EXPECT_EQ(a.eye, glm::vec3(0, 1, -5));
    EXPECT_EQ(a.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(a.fovY, 40.0f);
    EXPECT_EQ(b.eye, glm::vec3(3, 1, -4));
    EXPECT_EQ(b.up, glm::vec3(0, 0, 1));
    EXPECT_EQ(b.fovY, 60.0f);
    EXPECT_EQ(c.target, glm::vec3(0, 1, 0.5f));
    EXPECT_EQ(c.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(c.fovY, 60.0f);  // the previous keyframe's
}

TEST(CameraPathFile, EachMistakeIsAnErrorNamingTheFileAndTheKey) {
    const std::string key = R"({"time": 0, "eye": [0, 0, -5], "target": [0, 0, 0]})";
    struct Case {
        std::string text, expected;
    };
    const Case cases[] = {
        {"", "file is empty"},
        {"\x89PNG\r\n\x1a\n", "PNG"},
        {R"({"keyframes": [)", "invalid JSON"},
        {R"({"keyframes": [{"time": 1e999}]})", "invalid JSON"},
        {R"([1, 2])", "expected a JSON object at the top level"},
        {R"({})", "missing \"keyframes\""},
        {R"({"keyframes": [)" + key + R"(], "loop": true})", "loop: unknown key (expected keyframes)"},
        {R"({"keyframes": {"time": 0}})", "keyframes: expected an array of keyframes"},
        {R"({"keyframes": []})", "keyframes: expected at least 1 keyframe"},
        {R"({"keyframes": [)" + key + R"(, 3]})", "keyframes[1]: expected a JSON object, got 3"},
        {R"({"keyframes": [{"eye": [0, 0, -5], "target": [0, 0, 0]}]})", "keyframes[0]: missing \"time\""},
        {R"({"keyframes": [{"time": 0, "target": [0, 0, 0]}]})", "keyframes[0]: missing \"eye\""},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, -5]}]})", "keyframes[0]: missing \"target\""},
        {R"({"keyframes": [)" + key + R"(, )" + key +
             R"(, {"time": 2, "eye": [1, 2], "target": [0, 0, 0]}]})",
         "keyframes[2].eye: expected 3 numbers, got [1,2]"},
        {R"({"keyframes": [{"time": 0, "eye": [0, "1", -5], "target": [0, 0, 0]}]})",
         "keyframes[0].eye[1]: expected a number, got \"1\""},
        {R"({"keyframes": [{"time": 0, "eye": [0, 1e39, -5], "target": [0, 0, 0]}]})",
         "keyframes[0].eye[1]: expected a number within float range"},
        {R"({"keyframes": [{"time": "0", "eye": [0, 0, -5], "target": [0, 0, 0]}]})",
         "keyframes[0].time: expected a number, got \"0\""},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, -5], "target": [0, 0, 0], "up": null}]})",
         "keyframes[0].up: expected 3 numbers, got null"},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, -5], "target": [0, 0, 0], "fov": [40]}]})",
         "keyframes[0].fov: expected a number, got [40]"},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, -5], "target": [0, 0, 0], "fovy": 40}]})",
         "keyframes[0].fovy: unknown key (expected time, eye, target, up or fov)"},
        {R"({"keyframes": [)" + key + R"(, )" + key + R"(]})",
         "keyframes[1].time (0) must be after keyframes[0].time (0)"},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, 0], "target": [0, 0, 0]}]})",
         "keyframes[0].eye and keyframes[0].target are the same point"},
        {R"({"keyframes": [{"time": 0, "eye": [0, 0, -5], "target": [0, 0, 0], "fov": 180}]})",
         "keyframes[0].fov must be in (0, 180)"},
    };
    test::TempDir dir;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        std::string file = dir.write("path.json", c.text);
        EXPECT_CONTAINS_ALL(errorOf([&] { readCameraPath(file); }), file + ": ", c.expected);
    }
    std::string missing = dir.path("missing.json");
    EXPECT_CONTAINS_ALL(errorOf([&] { readCameraPath(missing); }), missing);
    EXPECT_CONTAINS_ALL(errorOf([&] { readCameraPath(dir.path()); }), dir.path());
}

}  // namespace
}  // namespace fp
