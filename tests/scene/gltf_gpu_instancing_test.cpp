// EXT_mesh_gpu_instancing: a node's mesh drawn once for each row of its TRANSLATION, ROTATION and SCALE
// accessors, each in the node's space; checked on a file the test writes (positions worked out by hand)
// and on the Khronos SimpleInstancing sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "gltf_samples.h"
#include "gltf_test_util.h"
#include "scene/instancing.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::GltfBuilder;

Scene loadFile(const std::string& name, const std::string& bytes) {
    test::TempDir dir;
    return loadScene(dir.write(name, bytes));
}

// One triangle under a node moved by (0, 10, 0), drawn twice by the extension.
GltfBuilder twoInstances(const json& attributes) {
    GltfBuilder b;
    int p = b.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    int mesh = b.mesh(json::array({{{"attributes", {{"POSITION", p}}}}}));
    json a = attributes;
    b.node({{"mesh", mesh},
            {"translation", {0, 10, 0}},
            {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", a}}}}}});
    b.scene({0});
    b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    return b;
}

TEST(GltfGpuInstancing, EachInstanceIsPlacedByItsRowInTheNodesSpace) {
    GltfBuilder b = twoInstances(json::object());
    const double s = std::sqrt(0.5);
    json attributes = {{"TRANSLATION", b.vec3({{1, 0, 0}, {0, 0, 5}})},
                       {"ROTATION", b.vec4({{0, 0, 0, 1}, {0, 0, float(s), float(s)}})},
                       {"SCALE", b.vec3({{1, 1, 1}, {2, 2, 2}})}};
    b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = attributes;
    WarningCapture capture;
    Scene flat = flattenInstances(loadFile("instanced.gltf", b.gltf()));
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(flat.triangles.size(), 2u);
    // Instance 0: moved by (1, 0, 0), then by the node's (0, 10, 0).
    std::vector<glm::vec3> first = {{1, 10, 0}, {2, 10, 0}, {1, 11, 0}};
    // Instance 1: scaled by 2, turned 90 degrees about +z ((x, y) -> (-y, x)), moved by (0, 0, 5), then
    // by the node's (0, 10, 0).
    std::vector<glm::vec3> second = {{0, 10, 5}, {0, 12, 5}, {-2, 10, 5}};
    auto matches = [](const Triangle& t, const std::vector<glm::vec3>& expected) {
        for (int k = 0; k < 3; ++k)
            if (glm::length(t.p[k] - expected[size_t(k)]) > 1e-5f) return false;
        return true;
    };
    EXPECT_TRUE(matches(flat.triangles[0], first) || matches(flat.triangles[1], first));
    EXPECT_TRUE(matches(flat.triangles[0], second) || matches(flat.triangles[1], second));
}

TEST(GltfGpuInstancing, BadAttributesAreClearErrors) {
    GltfBuilder counts = twoInstances(json::object());
    counts.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {
        {"TRANSLATION", counts.vec3({{1, 0, 0}, {0, 0, 5}})}, {"SCALE", counts.vec3({{1, 1, 1}})}};
    EXPECT_CONTAINS_ALL(test::errorOf([&] { loadFile("counts.gltf", counts.gltf()); }),
                        "attributes hold different numbers of instances (2 and 1)");

    GltfBuilder type = twoInstances(json::object());
    type.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {
        {"TRANSLATION", type.vec2({{1, 0}, {0, 0}})}};
    EXPECT_CONTAINS_ALL(test::errorOf([&] { loadFile("type.gltf", type.gltf()); }),
                        "TRANSLATION of nodes[0]");

    GltfBuilder none = twoInstances(json::object());
    EXPECT_CONTAINS_ALL(test::errorOf([&] { loadFile("none.gltf", none.gltf()); }),
                        "names none of TRANSLATION, ROTATION and SCALE");
}

// The sample: 125 unit cubes on a 5 x 5 x 5 grid of translations from 0 to 10, scales from 1 to 2 and
// rotations of up to 90 degrees (its README); without the extension it was one cube.
TEST(GltfGpuInstancing, SimpleInstancingSampleDrawsItsGridOf125Cubes) {
    WarningCapture capture;
    Scene scene = loadScene(test::gltfSample("SimpleInstancing", "glTF-Binary", "SimpleInstancing.glb"));
    EXPECT_EQ(test::joined(capture).find("ignoring extensions"), std::string::npos) << test::joined(capture);
    ASSERT_EQ(scene.instances.size(), 125u);
    std::set<std::tuple<int, int, int>> grid;
    for (const Instance& instance : scene.instances) {
        glm::vec3 t(instance.objectToWorld[3]);
        grid.insert({int(std::lround(t.x * 4)), int(std::lround(t.y * 4)), int(std::lround(t.z * 4))});
        for (int c = 0; c < 3; ++c) {
            float scale = glm::length(glm::vec3(instance.objectToWorld[c]));
            EXPECT_GE(scale, 1.0f - 1e-5f);
            EXPECT_LE(scale, 2.0f + 1e-5f);
        }
    }
    EXPECT_EQ(grid.size(), 125u);  // every point of the grid, once (translations in steps of 2.5)
    for (const auto& [x, y, z] : grid)
        for (int v : {x, y, z}) EXPECT_TRUE(v % 10 == 0 && v >= 0 && v <= 40) << v;
}

}  // namespace
}  // namespace fp
