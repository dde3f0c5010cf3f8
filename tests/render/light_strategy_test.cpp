// Which scenes --light-sampling auto samples by solid angle (pack/light_strategy.h; here beside the
// analytic lamp scenes it is tested on): those with an emitter
// close to the surface it faces, and no others.
#include <gtest/gtest.h>

#include "bvh/bvh.h"
#include "pack/light_strategy.h"
#include "render/analytic_lamp.h"
#include "scene/builtin_scene.h"

namespace fp {
namespace {

Bvh bvhOf(const Scene& scene) {
    AabbArray bounds;
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    return buildBinnedSah(bounds, BvhBuildOptions{});
}

bool choosesSolidAngle(const Scene& scene) {
    return emittersFaceCloseSurfaces(scene, bvhOf(scene));
}

TEST(LightStrategy, ALampCloseAboveAFloorIsSampledBySolidAngle) {
    for (const test::LampCase& c : test::lampCases())  // 0.2 and 0.02 of its side above the floor
        EXPECT_TRUE(choosesSolidAngle(test::lampOverFloor(c))) << c.name;
}

TEST(LightStrategy, TheCornellBoxIsSampledByArea) {
    // Its lamp subtends 0.05 sr from the floor and 0.29 sr from the top of the tall block.
    EXPECT_FALSE(choosesSolidAngle(builtinCornellBox()));
}

TEST(LightStrategy, ALampFarAboveTheFloorOrFacingNothingIsSampledByArea) {
    test::LampCase high{"unit lamp 3 sides up", 1.0, 3.0, 0.0};
    EXPECT_FALSE(choosesSolidAngle(test::lampOverFloor(high)));
    Scene upward = test::lampOverFloor(test::lampCases()[0]);
    for (Triangle& t : upward.triangles)
        if (t.material == 1) std::swap(t.p[1], t.p[2]);  // the lamp now emits up, into nothing
    EXPECT_FALSE(choosesSolidAngle(upward));
    Scene dark = test::lampOverFloor(test::lampCases()[0]);
    dark.materials[1].emission = glm::vec3(0.0f);
    EXPECT_FALSE(choosesSolidAngle(dark)) << "no emitter";
}

// The floor as an instance (stored in its own space 1 lower, placed 1 up): the surface the lamp faces
// is found through the instance's transform. Without the mesh's BVH (or placed 5 further down) the lamp
// faces nothing close.
TEST(LightStrategy, InstancesAreSurfacesToo) {
    Scene scene = test::lampOverFloor(test::lampCases()[0]);
    InstancedMesh floor{"floor", {}, {}};
    std::vector<Triangle> lamp;
    for (const Triangle& t : scene.triangles) (t.material == 1 ? lamp : floor.triangles).push_back(t);
    for (Triangle& t : floor.triangles)
        for (glm::vec3& p : t.p) p.y -= 1.0f;  // y is up in lampOverFloor's scenes
    scene.triangles = lamp;
    scene.meshes = {floor};
    glm::mat4 up(1.0f);
    up[3] = glm::vec4(0, 1, 0, 1);
    scene.instances = {{0, up}};
    AabbArray bounds;
    for (const Triangle& t : scene.meshes[0].triangles) bounds.push_back(t.bounds());
    std::vector<Bvh> meshBvhs = {buildBinnedSah(bounds, BvhBuildOptions{})};
    EXPECT_TRUE(emittersFaceCloseSurfaces(scene, bvhOf(scene), meshBvhs));
    EXPECT_FALSE(emittersFaceCloseSurfaces(scene, bvhOf(scene))) << "the world's triangles alone: the lamp";
    scene.instances[0].objectToWorld[3] = glm::vec4(0, -4, 0, 1);
    EXPECT_FALSE(emittersFaceCloseSurfaces(scene, bvhOf(scene), meshBvhs));
}

}  // namespace
}  // namespace fp
