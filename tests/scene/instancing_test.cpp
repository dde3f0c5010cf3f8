// scene/instancing.h and the glTF loader's instances: which meshes are stored once, where instances
// land in the world, flattening, and the checks the two-level BVH relies on.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "gltf_test_util.h"
#include "scene/instancing.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::GltfBuilder;

Triangle unitTriangle() {
    Triangle t;
    t.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    t.n = {glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)};
    return t;
}

Scene oneMesh(glm::mat4 a, glm::mat4 b) {
    Scene scene;
    scene.source = "s";
    scene.materials = {Material{}};
    scene.meshes.push_back({"tri", {unitTriangle()}, {}});
    scene.instances = {{0, a}, {0, b}};
    return scene;
}

TEST(Instancing, PlacedTrianglesBoundsAndCounts) {
    // Scaled 2 in x, then moved by (10, 0, 0): the normal of a sheared or scaled surface goes through the
    // inverse transpose, so a normal (1, 0, 1) / sqrt 2 becomes (1/2, 0, 1) normalised.
    glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)), glm::vec3(2, 1, 1));
    Triangle t = unitTriangle();
    t.n[0] = glm::normalize(glm::vec3(1, 0, 1));
    Triangle p = placedTriangle(t, m);
    EXPECT_EQ(p.p[1], glm::vec3(12, 0, 0));
    glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0, 1));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.n[0][k], expected[k], 1e-6f);

    Scene scene = oneMesh(m, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5)));
    scene.triangles.push_back(unitTriangle());  // a world triangle at the origin
    EXPECT_EQ(scene.triangleCount(), 3u);
    Aabb bounds = scene.bounds();
    EXPECT_EQ(bounds.lo, glm::vec3(0, 0, -5));
    EXPECT_EQ(bounds.hi, glm::vec3(12, 1, 0));
    Aabb first = instanceBounds(meshBounds(scene.meshes[0]), scene.instances[0].objectToWorld);
    EXPECT_EQ(first.lo, glm::vec3(10, 0, 0));
    EXPECT_EQ(first.hi, glm::vec3(12, 1, 0));
}

TEST(Instancing, FlatteningAppendsEveryInstanceInOrderWithItsTangents) {
    Scene scene = oneMesh(glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)),
                          glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 0, 1)));
    scene.triangles.push_back(unitTriangle());
    scene.meshes[0].tangents = {{glm::vec4(1, 0, 0, -1), glm::vec4(1, 0, 0, -1), glm::vec4(0, 0, 0, 0)}};
    Scene flat = flattenInstances(scene);
    EXPECT_TRUE(flat.meshes.empty());
    EXPECT_TRUE(flat.instances.empty());
    ASSERT_EQ(flat.triangles.size(), 3u);
    EXPECT_EQ(flat.triangles[1].p[0], glm::vec3(1, 0, 0));
    EXPECT_NEAR(flat.triangles[2].p[1].y, 1.0f, 1e-6f);  // (1, 0, 0) turned to (0, 1, 0)
    ASSERT_EQ(flat.tangents.size(), 3u);
    EXPECT_EQ(flat.tangents[0][0].w, 0.0f) << "the world triangle had none: computed when packing";
    EXPECT_NEAR(flat.tangents[2][0].y, 1.0f, 1e-6f) << "turned with the instance";
    EXPECT_EQ(flat.tangents[2][0].w, -1.0f);
    EXPECT_EQ(flat.tangents[2][2].w, 0.0f);
}

TEST(Instancing, ValidationRefusesWhatTheTwoLevelBvhCannotTrace) {
    glm::mat4 identity(1.0f);
    EXPECT_NO_THROW(validateInstances(oneMesh(identity, identity)));
    Scene mirrored = oneMesh(identity, glm::scale(identity, glm::vec3(-1, 1, 1)));
    EXPECT_CONTAINS_ALL(test::errorOf([&] { validateInstances(mirrored); }), "instance 1", "mirrors");
    Scene nan = oneMesh(identity, identity);
    nan.instances[0].objectToWorld[3][0] = std::nanf("");
    EXPECT_CONTAINS_ALL(test::errorOf([&] { validateInstances(nan); }), "instance 0", "non-finite");
    Scene emitter = oneMesh(identity, identity);
    emitter.materials[0].emission = glm::vec3(1.0f);
    EXPECT_CONTAINS_ALL(test::errorOf([&] { validateInstances(emitter); }), "'tri'", "emits light");
    Scene nowhere = oneMesh(identity, identity);
    nowhere.instances[1].mesh = 3;
    EXPECT_CONTAINS_ALL(test::errorOf([&] { validateInstances(nowhere); }), "instance 1 names no mesh");
}

// One quad primitive (two triangles) in z = 0 with `material`.
json quad(GltfBuilder& b, int material) {
    return {{"attributes", {{"POSITION", b.vec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})}}},
            {"indices", b.indices16({0, 1, 2, 0, 2, 3})},
            {"material", material}};
}

// A glTF mesh under several nodes is stored once and placed by each; a mirrored placement, a mesh used
// once and a mesh that emits light are world triangles.
TEST(Instancing, GltfMeshUnderSeveralNodesIsStoredOnce) {
    GltfBuilder b;
    int grey = b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}});
    int lamp = b.material({{"emissiveFactor", {1, 1, 1}}});
    int shared = b.mesh(json::array({quad(b, grey)}));
    int single = b.mesh(json::array({quad(b, grey)}));
    int glowing = b.mesh(json::array({quad(b, lamp)}));
    b.node({{"mesh", shared}, {"translation", {5, 0, 0}}});
    b.node({{"mesh", shared}, {"translation", {0, 5, 0}}, {"scale", {2, 2, 2}}});
    b.node({{"mesh", shared}, {"scale", {-1, 1, 1}}});  // mirrored: flattened
    b.node({{"mesh", single}});
    b.node({{"mesh", glowing}, {"translation", {0, 0, 1}}});
    b.node({{"mesh", glowing}, {"translation", {0, 0, 2}}});
    b.scene({0, 1, 2, 3, 4, 5});
    test::TempDir dir;
    Scene scene = loadScene(dir.write("m.gltf", b.gltf()));
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].triangles.size(), 2u);
    EXPECT_EQ(scene.meshes[0].triangles[0].p[1], glm::vec3(1, 0, 0)) << "in the mesh's own space";
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(glm::vec3(scene.instances[0].objectToWorld[3]), glm::vec3(5, 0, 0));
    EXPECT_EQ(glm::vec3(scene.instances[1].objectToWorld * glm::vec4(1, 0, 0, 1)), glm::vec3(2, 5, 0));
    EXPECT_EQ(scene.triangles.size(), 2u + 2u + 4u) << "the mirrored one, the single one, both lamps";
    EXPECT_EQ(scene.triangleCount(), 12u);
    EXPECT_EQ(scene.bounds().hi.x, 6.0f);
    // And the flattened copy is what the loader used to make: the same triangles, world first.
    Scene flat = flattenInstances(scene);
    ASSERT_EQ(flat.triangles.size(), 12u);
    EXPECT_EQ(flat.triangles[8].p[1], glm::vec3(6, 0, 0));
}

}  // namespace
}  // namespace fp
