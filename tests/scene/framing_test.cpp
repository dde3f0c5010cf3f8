// The default camera (scene/scene.h frameBounds): from the front (+z) and a little above, the whole
// bounding box in both fields of view for the image's aspect ratio, as model viewers frame a model.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.h"

namespace fp {
namespace {

// Where `p` lands in the image of `camera` at `aspect`: normalised device coordinates, [-1, 1]^2 inside.
glm::vec2 project(const Camera& camera, float aspect, const glm::vec3& p) {
    const CameraFrame f = cameraFrame(camera, aspect);
    const glm::vec3 d = p - f.eye;
    const float depth = glm::dot(d, f.forward);
    EXPECT_GT(depth, 0.0f) << "in front of the eye";
    // f.right and f.up are scaled by tan(fov / 2) (and the aspect): divide by their squared lengths.
    return {glm::dot(d, f.right) / glm::dot(f.right, f.right) / depth,
            glm::dot(d, f.up) / glm::dot(f.up, f.up) / depth};
}

// The largest |x| and |y| over the eight corners of the box.
glm::vec2 cornerReach(const Camera& camera, float aspect, const Aabb& box) {
    glm::vec2 reach(0.0f);
    for (int c = 0; c < 8; ++c) {
        glm::vec3 p((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                    (c & 4) ? box.hi.z : box.lo.z);
        reach = glm::max(reach, glm::abs(project(camera, aspect, p)));
    }
    return reach;
}

Aabb box(const glm::vec3& lo, const glm::vec3& hi) {
    Aabb b;
    b.grow(lo);
    b.grow(hi);
    return b;
}

TEST(Framing, FromTheFrontAndALittleAbove) {
    const Aabb b = box({-1, -2, -0.5f}, {3, 1, 0.5f});
    const Camera c = frameBounds(b, 40.0f, 4.0f / 3.0f);
    EXPECT_EQ(c.target, b.center());
    const glm::vec3 back = glm::normalize(c.eye - c.target);
    EXPECT_NEAR(back.x, 0.0f, 1e-6f);
    EXPECT_GT(back.z, 0.0f) << "the eye on the +z side, looking towards -z";
    EXPECT_NEAR(std::asin(back.y), glm::radians(kFrameElevationDegrees), 1e-5f);
    EXPECT_EQ(c.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(c.fovY, 40.0f);
}

// Every corner inside the image, and the box as large as the margin allows in the tighter direction:
// for a wide image the height binds, for a tall one the width.
TEST(Framing, TheWholeBoxFillsTheImageBehindTheMargin) {
    for (const Aabb& b :
         {box({-1, -1, -1}, {1, 1, 1}), box({0, 0, 0}, {10, 1, 1}), box({0, 0, 0}, {1, 10, 1}),
          box({-5, 0, -5}, {5, 0, 5}), box({2, 3, 4}, {2.5f, 3.1f, 40})})
        for (float aspect : {1.0f, 4.0f / 3.0f, 3.0f, 0.5f}) {
            const glm::vec2 reach = cornerReach(frameBounds(b, 40.0f, aspect), aspect, b);
            EXPECT_LE(reach.x, 1.0f / kFrameMargin + 1e-4f) << aspect;
            EXPECT_LE(reach.y, 1.0f / kFrameMargin + 1e-4f) << aspect;
            EXPECT_NEAR(std::max(reach.x, reach.y), 1.0f / kFrameMargin, 1e-4f)
                << "a corner touches the margin (aspect " << aspect << ")";
        }
}

// A flat model facing +z (a square in z = 0) is seen nearly face-on, filling the image; the old
// framing's eye was on -z, and one lying flat (y = 0) was seen edge-on.
TEST(Framing, AFlatModelIsSeenNotEdgeOn) {
    const Aabb facing = box({-1, -1, 0}, {1, 1, 0});
    const Camera c = frameBounds(facing, 40.0f, 1.0f);
    const glm::vec3 view = glm::normalize(c.target - c.eye);
    EXPECT_NEAR(glm::dot(-view, glm::vec3(0, 0, 1)), std::cos(glm::radians(kFrameElevationDegrees)), 1e-5f);
    const Aabb lying = box({-1, 0, -1}, {1, 0, 1});
    const Camera above = frameBounds(lying, 40.0f, 1.0f);
    const glm::vec2 reach = cornerReach(above, 1.0f, lying);
    // Seen from 15 degrees above, its near and far edges are apart on screen (edge-on: the same line).
    const float nearY = project(above, 1.0f, {0, 0, 1}).y, farY = project(above, 1.0f, {0, 0, -1}).y;
    EXPECT_GT(farY - nearY, 0.3f);
    EXPECT_NEAR(reach.x, 1.0f / kFrameMargin, 1e-4f);
}

TEST(Framing, APointOrAnEmptyBoxStillMakesACamera) {
    const Camera point = frameBounds(box({1, 2, 3}, {1, 2, 3}), 40.0f, 1.0f);
    EXPECT_NO_THROW(validateCamera(point, "camera"));
    EXPECT_GT(point.eye.z, 3.0f);
    EXPECT_NO_THROW(validateCamera(frameBounds(Aabb(), 40.0f, 1.0f), "camera"));
}

}  // namespace
}  // namespace fp
