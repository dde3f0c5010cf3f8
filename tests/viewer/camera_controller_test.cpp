// The viewer's camera math: each motion keeps what it promises to keep, the limits hold under abuse,
// version() tracks camera() exactly, and no sequence of calls produces a camera the renderer cannot use.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/error.h"
#include "scene/scene.h"
#include "viewer/camera_controller.h"

namespace fp {
namespace {

constexpr double kPi = 3.14159265358979323846;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();
const float kFloatMax = std::numeric_limits<float>::max();

Camera cornell() {
    return Camera{{278.0f, 273.0f, -800.0f}, {278.0f, 273.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 39.3f};
}

// An oblique camera with a non-unit z-up vector, so nothing relies on y-up or unit length.
Camera oblique() {
    return Camera{{1.0f, 2.0f, 3.0f}, {-0.5f, 0.25f, 0.1f}, {0.0f, 0.0f, 2.0f}, 50.0f};
}

// The renderer's basis (src/render/renderer.cpp), in double for measuring.
struct Basis {
    glm::dvec3 forward, right, up;
};
Basis basisOf(const Camera& c) {
    Basis b;
    b.forward = glm::normalize(glm::dvec3(c.target) - glm::dvec3(c.eye));
    b.right = glm::normalize(glm::cross(b.forward, glm::dvec3(c.up)));
    b.up = glm::cross(b.right, b.forward);
    return b;
}

double distanceOf(const Camera& c) {
    return glm::length(glm::dvec3(c.target) - glm::dvec3(c.eye));
}

// Angle in degrees between the view direction and world up (0: looking straight up).
double angleToUpDegrees(const Camera& c) {
    glm::dvec3 f = basisOf(c).forward, up = glm::normalize(glm::dvec3(c.up));
    return glm::degrees(std::acos(std::clamp(glm::dot(f, up), -1.0, 1.0)));
}

bool same(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovY == b.fovY;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What the renderer needs: the CLI's own validation passes and its float basis has no NaN or infinity.
::testing::AssertionResult renderable(const Camera& c) {
    try {
        validateCamera(c, "camera");
    } catch (const Error& e) {
        return ::testing::AssertionFailure() << e.what();
    }
    glm::vec3 forward = glm::normalize(c.target - c.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    glm::vec3 up = glm::cross(right, forward);
    if (!finite(forward) || !finite(right) || !finite(up))
        return ::testing::AssertionFailure() << "NaN basis";
    return ::testing::AssertionSuccess();
}

// Where point p lands on the image of camera c, in units of half the image height (the renderer's
// uCameraUp spans one unit): x to the right, y up.
glm::dvec2 project(const Camera& c, const glm::dvec3& p) {
    Basis b = basisOf(c);
    glm::dvec3 v = p - glm::dvec3(c.eye);
    double depth = glm::dot(v, b.forward) * std::tan(0.5 * glm::radians(double(c.fovY)));
    return {glm::dot(v, b.right) / depth, glm::dot(v, b.up) / depth};
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CameraController, StartsAtHome) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        EXPECT_TRUE(same(c.camera(), home));
        EXPECT_TRUE(same(c.home(), home));
        EXPECT_EQ(c.version(), 0u);
    }
}

TEST(CameraController, OrbitKeepsTargetDistanceAndUp) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        double d0 = distanceOf(home);
        const float steps[][2] = {{0.3f, 0.0f}, {0.0f, 0.4f}, {-1.2f, -0.7f}, {5.0f, 2.0f}, {1e6f, -1e6f}};
        for (const auto& s : steps) {
            c.orbit(s[0], s[1]);
            EXPECT_EQ(c.camera().target, home.target);
            EXPECT_EQ(c.camera().up, home.up);
            EXPECT_NEAR(distanceOf(c.camera()), d0, 1e-5 * d0);
            EXPECT_TRUE(renderable(c.camera()));
        }
    }
}

TEST(CameraController, OrbitByAFullTurnReturnsToTheStart) {
    for (const Camera& home : {cornell(), oblique()}) {
        double tolerance = 1e-5 * distanceOf(home);
        CameraController c(home);
        c.orbit(float(2.0 * kPi), 0.0f);
        expectNear(c.camera().eye, home.eye, tolerance);
        for (int i = 0; i < 8; ++i) c.orbit(float(kPi / 4.0), 0.0f);
        expectNear(c.camera().eye, home.eye, tolerance);
        // Pitching up and back down is also a round trip while away from the limit.
        c.orbit(0.0f, 0.5f);
        c.orbit(0.0f, -0.5f);
        expectNear(c.camera().eye, home.eye, tolerance);
    }
}

TEST(CameraController, OrbitSignConventions) {
    Camera home = oblique();
    Basis b = basisOf(home);
    glm::dvec3 up = glm::normalize(glm::dvec3(home.up));
    glm::dvec3 eye0(home.eye), target(home.target);

    CameraController c(home);
    c.orbit(0.1f, 0.0f);  // yaw > 0: the eye moves toward the camera's right, at the same height
    glm::dvec3 moved = glm::dvec3(c.camera().eye) - eye0;
    EXPECT_GT(glm::dot(moved, b.right), 0.0);
    EXPECT_NEAR(glm::dot(glm::dvec3(c.camera().eye) - target, up), glm::dot(eye0 - target, up), 1e-6);
    // The turn is by the requested angle about world up.
    glm::dvec3 h0 = (eye0 - target) - glm::dot(eye0 - target, up) * up;
    glm::dvec3 e1 = glm::dvec3(c.camera().eye) - target;
    glm::dvec3 h1 = e1 - glm::dot(e1, up) * up;
    EXPECT_NEAR(std::acos(glm::dot(glm::normalize(h0), glm::normalize(h1))), 0.1, 1e-5);

    c.reset();
    c.orbit(0.0f, 0.1f);  // pitch > 0: the eye rises, the view tilts down
    EXPECT_GT(glm::dot(glm::dvec3(c.camera().eye) - eye0, up), 0.0);
    EXPECT_GT(angleToUpDegrees(c.camera()), angleToUpDegrees(home));
    EXPECT_NEAR(angleToUpDegrees(c.camera()) - angleToUpDegrees(home), glm::degrees(0.1), 1e-3);
}

TEST(CameraController, PitchClampPreventsFlipping) {
    for (const Camera& home : {cornell(), oblique()}) {
        for (float sign : {1.0f, -1.0f}) {
            CameraController c(home);
            for (int i = 0; i < 200; ++i) {
                c.orbit(0.37f, sign * 1.3f);
                double angle = angleToUpDegrees(c.camera());
                ASSERT_GE(angle, 1.0 - 1e-4);
                ASSERT_LE(angle, 179.0 + 1e-4);
                ASSERT_TRUE(renderable(c.camera()));
            }
            // At the limit now: pushing further changes nothing, not even by rounding.
            EXPECT_NEAR(angleToUpDegrees(c.camera()), sign > 0 ? 179.0 : 1.0, 1e-4);
            Camera clamped = c.camera();
            uint64_t version = c.version();
            for (float push : {1e-3f, 0.5f, 3.0f, 1e6f}) {
                c.orbit(0.0f, sign * push);
                EXPECT_EQ(c.version(), version);
                EXPECT_TRUE(same(c.camera(), clamped));
            }
            // And it can come back.
            c.orbit(0.0f, -sign * 0.2f);
            EXPECT_EQ(c.version(), version + 1);
            EXPECT_NEAR(angleToUpDegrees(c.camera()),
                        sign > 0 ? 179.0 - glm::degrees(0.2) : 1.0 + glm::degrees(0.2), 1e-3);
        }
    }
}

TEST(CameraController, LookPitchClampPreventsFlipping) {
    for (float sign : {1.0f, -1.0f}) {
        CameraController c(oblique());
        for (int i = 0; i < 200; ++i) {
            c.look(-0.21f, sign * 0.9f);
            double angle = angleToUpDegrees(c.camera());
            ASSERT_GE(angle, 1.0 - 1e-4);
            ASSERT_LE(angle, 179.0 + 1e-4);
        }
        EXPECT_NEAR(angleToUpDegrees(c.camera()), sign > 0 ? 1.0 : 179.0, 1e-4);
        uint64_t version = c.version();
        Camera clamped = c.camera();
        c.look(0.0f, sign * 1e6f);
        c.look(0.0f, sign * 0.01f);
        EXPECT_EQ(c.version(), version);
        EXPECT_TRUE(same(c.camera(), clamped));
    }
}

TEST(CameraController, PanMovesEyeAndTargetTogetherInTheImagePlane) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        Basis b = basisOf(home);
        double d = distanceOf(home);
        double visibleHeight = 2.0 * d * std::tan(0.5 * glm::radians(double(home.fovY)));
        const float dx = 0.3f, dy = -0.2f;
        c.pan(dx, dy);
        glm::dvec3 eyeMove = glm::dvec3(c.camera().eye) - glm::dvec3(home.eye);
        glm::dvec3 targetMove = glm::dvec3(c.camera().target) - glm::dvec3(home.target);
        double tolerance = 1e-6 * (d + glm::length(glm::dvec3(home.target)));
        expectNear(eyeMove, targetMove, tolerance);
        EXPECT_NEAR(glm::dot(eyeMove, b.forward), 0.0, tolerance);
        EXPECT_NEAR(glm::length(eyeMove), std::hypot(double(dx), double(dy)) * visibleHeight, tolerance);
        // dx > 0 along right, dy < 0 against image up, each by its own share of the visible height.
        EXPECT_NEAR(glm::dot(eyeMove, b.right), dx * visibleHeight, tolerance);
        EXPECT_NEAR(glm::dot(eyeMove, b.up), dy * visibleHeight, tolerance);
        // The view direction and distance are untouched.
        expectNear(basisOf(c.camera()).forward, b.forward, 1e-6);
        EXPECT_NEAR(distanceOf(c.camera()), d, 1e-6 * d);
    }
}

TEST(CameraController, FullHeightPanMovesTheTargetPointByTheVisibleHeight) {
    Camera home = oblique();
    glm::dvec3 point(home.target);
    {
        CameraController c(home);
        c.pan(0.0f, 1.0f);
        // The point was at the image centre; the camera rose by the visible height, so the point now
        // sits one full image height (two half-heights) lower, on the same column.
        glm::dvec2 p = project(c.camera(), point);
        EXPECT_NEAR(p.x, 0.0, 1e-5);
        EXPECT_NEAR(p.y, -2.0, 1e-5);
    }
    {
        CameraController c(home);
        c.pan(0.25f, -0.125f);  // camera right and down: the scene slides left and up
        glm::dvec2 p = project(c.camera(), point);
        EXPECT_NEAR(p.x, -0.5, 1e-5);
        EXPECT_NEAR(p.y, 0.25, 1e-5);
    }
}

TEST(CameraController, DollyScalesTheDistanceExponentially) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        double d0 = distanceOf(home);
        Basis b = basisOf(home);
        c.dolly(0.5f);
        EXPECT_NEAR(distanceOf(c.camera()), d0 * std::exp(-0.5), 1e-6 * d0);
        EXPECT_EQ(c.camera().target, home.target);
        expectNear(basisOf(c.camera()).forward, b.forward, 1e-6);
        c.dolly(-1.5f);
        EXPECT_NEAR(distanceOf(c.camera()), d0 * std::exp(1.0), 1e-6 * d0);
    }
}

TEST(CameraController, DollyThereAndBackRestoresTheDistance) {
    for (const Camera& home : {cornell(), oblique()}) {
        for (float a : {0.1f, 1.0f, 3.0f, -2.5f}) {
            CameraController c(home);
            c.dolly(a);
            c.dolly(-a);
            EXPECT_NEAR(distanceOf(c.camera()), distanceOf(home), 1e-6 * distanceOf(home));
            expectNear(c.camera().eye, home.eye, 1e-5 * distanceOf(home));
        }
    }
}

TEST(CameraController, DollyNeverReachesOrPassesTheTarget) {
    for (const Camera& home : {cornell(), oblique()}) {
        double d0 = distanceOf(home);
        Basis b = basisOf(home);
        for (float amount : {1e6f, kFloatMax, 50.0f}) {
            CameraController c(home);
            for (int i = 0; i < 20; ++i) c.dolly(amount);
            double d = distanceOf(c.camera());
            EXPECT_GT(d, 0.0);
            EXPECT_NEAR(d, CameraController::kMinDistanceRatio * d0, 1e-3 * d);
            EXPECT_GT(glm::dot(basisOf(c.camera()).forward, b.forward), 0.999999);  // still in front
            EXPECT_NE(c.camera().eye, c.camera().target);
            EXPECT_TRUE(renderable(c.camera()));
            // At the limit, further dollying in is a no-op.
            uint64_t version = c.version();
            c.dolly(amount);
            EXPECT_EQ(c.version(), version);
        }
        CameraController out(home);
        out.dolly(-kFloatMax);
        out.dolly(-1e6f);
        EXPECT_NEAR(distanceOf(out.camera()), CameraController::kMaxDistanceRatio * d0,
                    1e-5 * CameraController::kMaxDistanceRatio * d0);
        EXPECT_TRUE(renderable(out.camera()));
    }
}

TEST(CameraController, DollyNearLargeCoordinatesKeepsTheEyeOffTheTarget) {
    // Far from the origin, float spacing (0.06 at 1e6) is coarser than the home distance's 1e-4 floor.
    Camera home{{1e6f, 1e6f, 1e6f + 1.0f}, {1e6f, 1e6f, 1e6f}, {0.0f, 1.0f, 0.0f}, 40.0f};
    CameraController c(home);
    c.dolly(1e6f);
    EXPECT_NE(c.camera().eye, c.camera().target);
    EXPECT_TRUE(renderable(c.camera()));
    EXPECT_GT(glm::dot(basisOf(c.camera()).forward, glm::dvec3(0, 0, -1)), 0.9999);
}

TEST(CameraController, FlyMovesEyeAndTargetAlongTheCameraAxes) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        Basis b = basisOf(home);
        glm::vec3 move(1.5f, -2.0f, 3.25f);
        c.fly(move);
        glm::dvec3 expected = double(move.x) * b.right + double(move.y) * b.up + double(move.z) * b.forward;
        double tolerance = 1e-6 * (1.0 + glm::length(glm::dvec3(home.eye)));
        expectNear(glm::dvec3(c.camera().eye) - glm::dvec3(home.eye), expected, tolerance);
        expectNear(glm::dvec3(c.camera().target) - glm::dvec3(home.target), expected, tolerance);
        expectNear(basisOf(c.camera()).forward, b.forward, 1e-6);
    }
}

TEST(CameraController, LookTurnsAboutTheEye) {
    for (const Camera& home : {cornell(), oblique()}) {
        Basis b = basisOf(home);
        double d0 = distanceOf(home);
        CameraController c(home);
        c.look(0.2f, 0.0f);  // yaw > 0 turns right, at the same elevation
        EXPECT_EQ(c.camera().eye, home.eye);
        EXPECT_NEAR(distanceOf(c.camera()), d0, 1e-5 * d0);
        EXPECT_GT(glm::dot(basisOf(c.camera()).forward, b.right), 0.0);
        EXPECT_NEAR(angleToUpDegrees(c.camera()), angleToUpDegrees(home), 1e-4);

        c.reset();
        c.look(0.0f, 0.1f);  // pitch > 0 tilts up
        EXPECT_EQ(c.camera().eye, home.eye);
        EXPECT_NEAR(distanceOf(c.camera()), d0, 1e-5 * d0);
        EXPECT_NEAR(angleToUpDegrees(home) - angleToUpDegrees(c.camera()), glm::degrees(0.1), 1e-3);

        for (int i = 0; i < 50; ++i) c.look(1e6f, -1e6f);
        EXPECT_EQ(c.camera().eye, home.eye);
        EXPECT_NEAR(distanceOf(c.camera()), d0, 1e-5 * d0);
        EXPECT_TRUE(renderable(c.camera()));
    }
}

TEST(CameraController, ResetReturnsExactlyHome) {
    for (const Camera& home : {cornell(), oblique()}) {
        CameraController c(home);
        c.orbit(0.7f, 0.3f);
        c.pan(0.1f, 0.2f);
        c.dolly(2.0f);
        c.fly({1.0f, 2.0f, 3.0f});
        c.look(-0.4f, 0.2f);
        c.setFov(90.0f);
        uint64_t version = c.version();
        c.reset();
        EXPECT_TRUE(same(c.camera(), home));
        EXPECT_EQ(c.version(), version + 1);
        c.reset();  // already home: nothing changes
        EXPECT_EQ(c.version(), version + 1);
        // The motions start from home again, not from a remembered state.
        c.orbit(0.1f, 0.0f);
        CameraController fresh(home);
        fresh.orbit(0.1f, 0.0f);
        EXPECT_TRUE(same(c.camera(), fresh.camera()));
    }
}

// The thin lens travels with the camera: motions keep it, the panel sets it, reset brings home's back.
// A focus distance left unset follows the target (the distance resolvedFocusDistance gives changes with
// a dolly); one that is set stays where it was put.
TEST(CameraController, TheLensIsKeptSetAndReset) {
    Camera home = cornell();
    home.aperture = 20.0f;
    CameraController c(home);
    EXPECT_EQ(c.camera().aperture, 20.0f);
    EXPECT_FALSE(c.camera().focusDistance);
    c.dolly(0.5f);
    EXPECT_EQ(c.camera().aperture, 20.0f);
    EXPECT_NEAR(resolvedFocusDistance(c.camera()), distanceOf(c.camera()), 1e-3);
    EXPECT_LT(resolvedFocusDistance(c.camera()), 799.0f);

    uint64_t version = c.version();
    c.setFocusDistance(650.0f);
    EXPECT_EQ(c.camera().focusDistance, 650.0f);
    EXPECT_EQ(c.version(), version + 1) << "a new focus restarts accumulation";
    c.orbit(0.3f, 0.1f);
    c.dolly(-0.2f);
    EXPECT_EQ(c.camera().focusDistance, 650.0f);
    version = c.version();
    c.setFocusDistance(650.0f);
    EXPECT_EQ(c.version(), version) << "the same focus again changes nothing";
    for (float bad : {0.0f, -1.0f, kNaN, kInf}) c.setFocusDistance(bad);
    EXPECT_EQ(c.camera().focusDistance, 650.0f);
    EXPECT_EQ(c.version(), version);

    c.setAperture(35.0f);
    EXPECT_EQ(c.camera().aperture, 35.0f);
    EXPECT_EQ(c.version(), version + 1);
    c.setAperture(-3.0f);  // a pinhole
    EXPECT_EQ(c.camera().aperture, 0.0f);
    c.setAperture(kNaN);
    EXPECT_EQ(c.camera().aperture, 0.0f);
    c.setFocusDistance(std::nullopt);
    EXPECT_FALSE(c.camera().focusDistance);

    c.setAperture(5.0f);
    c.reset();
    EXPECT_EQ(c.camera().aperture, 20.0f);
    EXPECT_FALSE(c.camera().focusDistance);
    EXPECT_TRUE(renderable(c.camera()));

    // A home lens that cannot be rendered is repaired to a pinhole focused on the target.
    home.aperture = -1.0f;
    home.focusDistance = kNaN;
    CameraController repaired(home);
    EXPECT_EQ(repaired.camera().aperture, 0.0f);
    EXPECT_FALSE(repaired.camera().focusDistance);
}

TEST(CameraController, SetFovClamps) {
    CameraController c(cornell());
    c.setFov(60.0f);
    EXPECT_EQ(c.camera().fovY, 60.0f);
    c.setFov(0.0f);
    EXPECT_EQ(c.camera().fovY, 1.0f);
    c.setFov(-30.0f);
    EXPECT_EQ(c.camera().fovY, 1.0f);
    c.setFov(1000.0f);
    EXPECT_EQ(c.camera().fovY, 170.0f);
    c.setFov(kNaN);
    c.setFov(kInf);
    EXPECT_EQ(c.camera().fovY, 170.0f);
    EXPECT_TRUE(renderable(c.camera()));
}

TEST(CameraController, CallsThatChangeNothingKeepTheVersion) {
    CameraController c(oblique());
    const Camera before = c.camera();
    c.orbit(0.0f, 0.0f);
    c.pan(0.0f, 0.0f);
    c.pan(-0.0f, 0.0f);
    c.dolly(0.0f);
    c.fly(glm::vec3(0.0f));
    c.look(0.0f, 0.0f);
    c.setFov(before.fovY);
    c.reset();
    EXPECT_EQ(c.version(), 0u);
    EXPECT_TRUE(same(c.camera(), before));

    // Each real motion bumps it by exactly one.
    uint64_t v = c.version();
    c.orbit(0.1f, 0.0f);
    EXPECT_EQ(c.version(), ++v);
    c.pan(0.1f, 0.0f);
    EXPECT_EQ(c.version(), ++v);
    c.dolly(0.1f);
    EXPECT_EQ(c.version(), ++v);
    c.fly({0.0f, 0.0f, 0.1f});
    EXPECT_EQ(c.version(), ++v);
    c.look(0.1f, 0.0f);
    EXPECT_EQ(c.version(), ++v);
    c.setFov(45.0f);
    EXPECT_EQ(c.version(), ++v);
    c.setFov(45.0f);
    EXPECT_EQ(c.version(), v);
    c.setFov(500.0f);
    EXPECT_EQ(c.version(), ++v);
    c.setFov(171.0f);  // clamps to the value it already has
    EXPECT_EQ(c.version(), v);
}

TEST(CameraController, NonFiniteInputsAreIgnored) {
    CameraController c(oblique());
    c.orbit(0.3f, 0.2f);  // somewhere other than home
    const Camera before = c.camera();
    const uint64_t version = c.version();
    for (float bad : {kNaN, kInf, -kInf}) {
        c.orbit(bad, 0.0f);
        c.orbit(0.1f, bad);
        c.pan(bad, 0.1f);
        c.pan(0.1f, bad);
        c.dolly(bad);
        c.fly({bad, 1.0f, 1.0f});
        c.fly({1.0f, 1.0f, bad});
        c.look(bad, 0.1f);
        c.look(0.1f, bad);
        c.setFov(bad);
    }
    EXPECT_TRUE(same(c.camera(), before));
    EXPECT_EQ(c.version(), version);
}

TEST(CameraController, HugeTranslationsAreRefusedNotOverflowed) {
    CameraController c(cornell());
    const Camera before = c.camera();
    c.pan(kFloatMax, kFloatMax);
    c.pan(1e30f, -1e30f);
    c.fly({kFloatMax, -kFloatMax, kFloatMax});
    c.fly({1e12f, 0.0f, 0.0f});
    EXPECT_TRUE(same(c.camera(), before));
    EXPECT_EQ(c.version(), 0u);
    // Moves within a generous radius still work.
    c.pan(1000.0f, 0.0f);
    EXPECT_FALSE(same(c.camera(), before));
    EXPECT_TRUE(renderable(c.camera()));
}

TEST(CameraController, SuggestedFlySpeedFollowsTheDistance) {
    CameraController c(cornell());
    EXPECT_FLOAT_EQ(c.suggestedFlySpeed(), 200.0f);
    c.dolly(std::log(2.0f));
    EXPECT_NEAR(c.suggestedFlySpeed(), 100.0f, 1e-3f);
}

TEST(CameraController, DegenerateHomesAreRepaired) {
    const std::vector<Camera> homes = {
        {{kNaN, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},     // NaN eye
        {{1.0f, 2.0f, 3.0f}, {1.0f, 2.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},     // eye == target
        {{0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},     // looking straight down
        {{0.0f, -5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, 40.0f},    // straight up
        {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 40.0f},     // zero up
        {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {kInf, 1.0f, 0.0f}, 40.0f},     // infinite up
        {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f},      // zero fov
        {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, kNaN},      // NaN fov
        {{1e30f, 0.0f, 5.0f}, {-1e30f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},  // beyond float range
        {{0.0f, 0.0f, 1e-30f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},   // vanishing distance
        {{kNaN, kNaN, kNaN}, {kInf, kNaN, 0.0f}, {kNaN, 0.0f, 0.0f}, -kInf},     // everything wrong
    };
    for (const Camera& home : homes) {
        CameraController c(home);
        EXPECT_TRUE(renderable(c.camera()));
        EXPECT_TRUE(same(c.camera(), c.home()));
        c.orbit(0.5f, 0.5f);
        c.dolly(3.0f);
        c.look(-0.5f, -0.5f);
        c.pan(0.5f, 0.5f);
        EXPECT_TRUE(renderable(c.camera()));
        c.reset();
        EXPECT_TRUE(same(c.camera(), c.home()));
    }
    // A view parallel to up is tilted to the elevation limit, on the side the eye was.
    CameraController down(homes[2]);
    EXPECT_NEAR(angleToUpDegrees(down.camera()), 179.0, 1e-3);
    CameraController up(homes[3]);
    EXPECT_NEAR(angleToUpDegrees(up.camera()), 1.0, 1e-3);
}

TEST(CameraController, HomeBeyondTheLimitsIsKeptAndCanMoveBackInside) {
    // Valid for the renderer (0.5 degrees from up) but beyond the orbit's 1-degree margin.
    float angle = float(glm::radians(0.5));
    Camera home{{std::sin(angle), -std::cos(angle), 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
    CameraController c(home);
    EXPECT_TRUE(same(c.camera(), home));
    c.orbit(0.0f, -0.1f);  // further toward up: stopped where it is
    EXPECT_EQ(c.version(), 0u);
    c.orbit(0.3f, 0.0f);  // yaw alone keeps the elevation
    EXPECT_NEAR(angleToUpDegrees(c.camera()), 0.5, 1e-3);
    c.orbit(0.0f, 0.1f);  // back toward the horizon
    EXPECT_NEAR(angleToUpDegrees(c.camera()), 0.5 + glm::degrees(0.1), 1e-3);
}

// A long deterministic stream of calls with extreme and invalid arguments: the camera stays renderable,
// and the version moves by one exactly when camera() changes.
TEST(CameraController, NoSequenceOfCallsBreaksTheCamera) {
    const float values[] = {0.0f,       -0.0f, 1e-30f, 1e-7f, 0.01f, -0.01f, 0.5f,   -0.5f,
                            3.0f,       -3.0f, 100.0f, 1e6f,  -1e6f, 1e30f,  -1e30f, kFloatMax,
                            -kFloatMax, kNaN,  kInf,   -kInf, 0.25f, -2.0f};
    const int valueCount = int(sizeof(values) / sizeof(values[0]));
    const Camera farAway{{1e7f, -3e6f, 2e7f}, {1e7f + 0.5f, -3e6f, 2e7f + 3.0f}, {0.0f, 1.0f, 0.0f}, 40.0f};
    for (const Camera& home : {cornell(), oblique(), farAway}) {
        std::mt19937_64 random(12345);  // the engine's output is fixed by the standard
        auto pick = [&] { return values[random() % uint64_t(valueCount)]; };
        CameraController c(home);
        int changes = 0;
        for (int i = 0; i < 20000; ++i) {
            const Camera before = c.camera();
            const uint64_t version = c.version();
            switch (random() % 8) {
                case 0:
                    c.orbit(pick(), pick());
                    break;
                case 1:
                    c.pan(pick(), pick());
                    break;
                case 2:
                    c.dolly(pick());
                    break;
                case 3:
                    c.fly({pick(), pick(), pick()});
                    break;
                case 4:
                    c.look(pick(), pick());
                    break;
                case 5:
                    c.setFov(pick());
                    break;
                case 6:
                    c.orbit(pick(), 0.0f);
                    break;
                default:
                    if (random() % 50 == 0) c.reset();
                    break;
            }
            ASSERT_TRUE(renderable(c.camera())) << "call " << i;
            ASSERT_EQ(c.camera().up, home.up);
            ASSERT_GE(c.camera().fovY, 1.0f);
            ASSERT_LE(c.camera().fovY, 170.0f);
            ASSERT_TRUE(std::isfinite(c.suggestedFlySpeed()) && c.suggestedFlySpeed() > 0.0f);
            ASSERT_EQ(c.version(), version + (same(c.camera(), before) ? 0u : 1u)) << "call " << i;
            changes += same(c.camera(), before) ? 0 : 1;
        }
        EXPECT_GT(changes, 5000);  // the stream really moves the camera, not only hits the guards
    }
}

}  // namespace
}  // namespace fp
