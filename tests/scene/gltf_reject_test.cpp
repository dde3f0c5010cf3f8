// Bad glTF input: each way a file can be malformed, out of range, cyclic, truncated, non-finite or too
// large gets one fp::Error naming the file and the part of it, never a crash, a hang or a huge allocation.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>

#include "gltf_test_util.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::GltfBuilder;

// A valid file: one indexed triangle (accessors 0 POSITION, 1 NORMAL, 2 indices) on node 0.
GltfBuilder valid() {
    GltfBuilder b;
    int p = b.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    int n = b.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    int i = b.indices16({0, 1, 2});
    b.mesh(json::array({{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}, {"indices", i}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    return b;
}

std::string rejected(const std::string& name, const std::string& bytes) {
    test::TempDir dir;
    std::string path = dir.write(name, bytes);
    return test::errorOf([&] { loadScene(path); });
}

// The message for the valid file's JSON (as written with its data URI) changed by `edit`.
std::string rejectedEdit(const std::function<void(json&)>& edit, GltfBuilder b = valid()) {
    json doc = json::parse(b.gltf());
    edit(doc);
    return rejected("bad.gltf", doc.dump());
}

TEST(GltfReject, TheValidFileLoads) {
    test::TempDir dir;
    EXPECT_EQ(loadScene(dir.write("ok.gltf", valid().gltf())).triangles.size(), 1u);
    EXPECT_EQ(loadScene(dir.write("ok.glb", valid().glb())).triangles.size(), 1u);
}

TEST(GltfReject, NotJsonOrNotGltf) {
    EXPECT_CONTAINS_ALL(rejected("a.gltf", ""), "a.gltf: file is empty");
    EXPECT_CONTAINS_ALL(rejected("a.gltf", "{\"asset\": {\"version\": \"2.0\"},"),
                        "a.gltf: invalid JSON: ", "line 1");
    EXPECT_CONTAINS_ALL(rejected("a.gltf", "[1, 2]"), "a.gltf: the top level: must be a JSON object");
    EXPECT_CONTAINS_ALL(rejected("a.gltf", "{}"), "a.gltf: the top level: missing \"asset\"");
    EXPECT_CONTAINS_ALL(rejected("a.gltf", R"({"asset": {"version": "1.0"}})"),
                        "a.gltf: asset.version: '1.0': only glTF 2.0 files are supported");
    EXPECT_CONTAINS_ALL(rejected("a.gltf", std::string("{\0}", 3)), "a.gltf: contains binary data");
    std::string deep =
        R"({"asset": {"version": "2.0"}, "extras": )" + std::string(100, '[') + std::string(100, ']') + "}";
    EXPECT_CONTAINS_ALL(rejected("a.gltf", deep), "a.gltf: JSON nested deeper than 64 levels");
}

TEST(GltfReject, RequiredExtensionsWeDoNotImplement) {
    auto requiring = [](const char* extension) {
        return rejectedEdit([&](json& d) { d["extensionsRequired"] = {extension}; });
    };
    EXPECT_CONTAINS_ALL(requiring("KHR_meshopt_compression"),
                        "bad.gltf: buffers compressed with KHR_meshopt_compression are not supported (only "
                        "EXT_meshopt_compression is");
    EXPECT_CONTAINS_ALL(requiring("KHR_materials_iridescence"),
                        "bad.gltf: the file requires the extension KHR_materials_iridescence, which fragpath "
                        "does not implement");
    // A Draco primitive is decoded whether or not the file declares the extension (its data is checked:
    // tests/scene/gltf_compressed_test.cpp).
    std::string message = rejectedEdit([](json& d) {
        d["meshes"][0]["primitives"][0]["extensions"] = {
            {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    });
    EXPECT_CONTAINS_ALL(message,
                        "bad.gltf: meshes[0].primitives[0] (KHR_draco_mesh_compression): bufferViews[0] ");
}

TEST(GltfReject, SchemaErrorsNameTheProperty) {
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0]["mesh"] = 7; }),
                        "bad.gltf: nodes[0].mesh: meshes[7] does not exist (the file has 1)");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0]["mesh"] = -1; }),
                        "bad.gltf: nodes[0].mesh: must be an index into meshes (an integer from 0), got -1");
    // tinygltf would silently ignore these two.
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0]["mesh"] = 0.5; }),
                        "nodes[0].mesh: must be an index into meshes");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0]["mesh"] = "0"; }),
                        "nodes[0].mesh: must be an index into meshes");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["scene"] = 3; }),
                        "bad.gltf: scene: scenes[3] does not exist");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["accessors"][0]["count"] = 0; }),
                        "bad.gltf: accessors[0].count: must be in [1, ");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["accessors"][0]["componentType"] = 5130; }),
                        "accessors[0].componentType: 5130 is not a glTF 2.0 component type");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["bufferViews"][0]["byteStride"] = 6; }),
                        "bufferViews[0].byteStride: must be a multiple of 4, got 6");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 7; }),
                        "meshes[0].primitives[0].mode: must be in [0, 6], got 7");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
                            d["nodes"][0]["scale"] = {1, 1, 1};
                        }),
                        "bad.gltf: nodes[0]: has both a matrix and translation/rotation/scale");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"][0]["matrix"] = {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
                        }),
                        "nodes[0].matrix: must be an affine transform");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"][0]["rotation"] = {0, 0, 0, 0};
                        }),
                        "nodes[0].rotation: is not a rotation");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) {
            d["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 2, 1}}}}}};
        }),
        "materials[0].pbrMetallicRoughness.baseColorFactor[2]: must be in [0.0, 1.0], got 2");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) {
            d["materials"] = {{{"extensions", {{"KHR_materials_volume", {{"attenuationDistance", 0}}}}}}};
        }),
        "materials[0].extensions.KHR_materials_volume.attenuationDistance: must be in (0.0, "
        "infinity), got 0");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) {
            d["materials"] = {
                {{"extensions", {{"KHR_materials_volume", {{"attenuationColor", {1, -1, 1}}}}}}}};
        }),
        "materials[0].extensions.KHR_materials_volume.attenuationColor[1]: must be in [0.0, 1.0]");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) {
            d["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0}, {"znear", 1}}}}};
        }),
        "cameras[0].perspective.yfov: must be in (0.0, infinity), got 0");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["buffers"][0]["uri"] = "http://example.com/a.bin"; }),
        "buffers[0].uri: 'http://example.com/a.bin' is not a relative file path or a data URI");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["buffers"][0].erase("uri"); }),
                        "bad.gltf: buffers[0]: has no uri (only the first buffer of a .glb may omit it");
}

TEST(GltfReject, ByteRangesBeyondTheirBuffers) {
    // Buffer views beyond the buffer (checked before tinygltf reads image views unchecked).
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["bufferViews"][1]["byteLength"] = 1000; }),
        "bad.gltf: bufferViews[1]: bytes 36 to 1036 lie beyond the end of buffers[0] (78 bytes)");
    // An accessor beyond its buffer view.
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["accessors"][0]["count"] = 4; }),
        "bad.gltf: accessors[0] (POSITION of meshes[0].primitives[0]) needs 4 elements of 12 bytes, "
        "every 12 bytes from byte 0, more than the 36 bytes of bufferViews[0]");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["accessors"][1]["byteOffset"] = 8; }),
                        "accessors[1] (NORMAL of meshes[0].primitives[0]) needs 3 elements");
    // A huge count is refused from its byte size, before anything is allocated, at once.
    auto start = std::chrono::steady_clock::now();
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["accessors"][2]["count"] = uint64_t(1) << 52; }),
        "accessors[2] (indices of meshes[0].primitives[0]) needs 4503599627370496 elements of 2 bytes");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    // The data URI must hold byteLength bytes, in base64.
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["buffers"][0]["byteLength"] = 84; }),
                        "bad.gltf: buffers[0]: its data URI holds 78 bytes, but byteLength says 84");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            std::string uri = d["buffers"][0]["uri"];
                            uri[45] = '*';
                            d["buffers"][0]["uri"] = uri;
                        }),
                        "buffers[0].uri: its base64 data has a character that is not base64 at offset 8");
}

TEST(GltfReject, IndicesBeyondTheVertices) {
    GltfBuilder b = valid();
    b.bin.replace(72, 6, GltfBuilder::raw(std::vector<uint16_t>{0, 1, 5}));
    EXPECT_CONTAINS_ALL(
        rejected("bad.gltf", b.gltf()),
        "bad.gltf: accessors[2] (indices of meshes[0].primitives[0]) holds index 5 (element 2), beyond "
        "the 3 vertices of POSITION");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["accessors"][1]["count"] = 2; }),
        "accessors[1] (NORMAL of meshes[0].primitives[0]) has 2 elements, but POSITION has 3");
}

TEST(GltfReject, NodeGraphsThatAreNotTrees) {
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0]["children"] = {0}; }),
                        "bad.gltf: nodes[0] is its own ancestor (it lists itself among its children)");
    // 1 -> 2 -> 3 -> 1, reachable from no scene: still refused (a file with a cycle is broken).
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"].push_back({{"children", {2}}});
                            d["nodes"].push_back({{"children", {3}}});
                            d["nodes"].push_back({{"children", {1}}});
                        }),
                        "bad.gltf: nodes[1] is its own ancestor (parent chain 1 -> 3 -> 2 -> 1)");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"].push_back({{"children", {0}}});
                            d["nodes"].push_back({{"children", {0}}});
                        }),
                        "bad.gltf: nodes[0] is a child of both nodes[1] and nodes[2]");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"].push_back({{"children", {0}}});
                            d["scenes"][0]["nodes"] = {1, 0};
                        }),
                        "bad.gltf: scenes[0].nodes lists nodes[0], which is a child of nodes[1]");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["scenes"][0]["nodes"] = {0, 0};
                        }),
                        "scenes[0].nodes[1]: lists nodes[0] twice");
}

TEST(GltfReject, MissingBufferFile) {
    test::TempDir dir;
    std::string path = dir.write("sub/model.gltf", valid().gltf("gone.bin"));
    EXPECT_CONTAINS_ALL(test::errorOf([&] { loadScene(path); }),
                        path + ": buffer file 'gone.bin' not found or unreadable (looked for " +
                            dir.path("sub/gone.bin") + ")");
}

TEST(GltfReject, NonFiniteValues) {
    GltfBuilder b = valid();
    float nan = std::numeric_limits<float>::quiet_NaN();
    b.bin.replace(12, 4, std::string(reinterpret_cast<const char*>(&nan), 4));
    EXPECT_CONTAINS_ALL(
        rejected("bad.gltf", b.gltf()),
        "bad.gltf: accessors[0] (POSITION of meshes[0].primitives[0]) holds a non-finite value (element 1)");
    b = valid();
    float inf = std::numeric_limits<float>::infinity();
    b.bin.replace(36 + 8, 4, std::string(reinterpret_cast<const char*>(&inf), 4));
    EXPECT_CONTAINS_ALL(
        rejected("bad.gltf", b.gltf()),
        "accessors[1] (NORMAL of meshes[0].primitives[0]) holds a non-finite value (element 0)");
    // JSON has no infinity, but large numbers make one.
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"][0]["scale"] = {1e300, 1e300, 1e300};
                            d["nodes"].push_back({{"scale", {1e300, 1, 1}}, {"children", {0}}});
                            d["scenes"][0]["nodes"] = {1};
                        }),
                        "bad.gltf: the transform of nodes[0] (with its ancestors') is not finite");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) {
                            d["nodes"][0]["translation"] = {1e30, 0, 0};
                        }),
                        "bad.gltf: vertex 0 of meshes[0].primitives[0] lies beyond +-1e18 (or at infinity) "
                        "once placed by nodes[0]");
}

TEST(GltfReject, DataTheLoaderDoesNotRead) {
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["accessors"][0]["componentType"] = 5125; }),
        "accessors[0] (POSITION of meshes[0].primitives[0]) must be VEC3 of FLOAT, BYTE, UNSIGNED_BYTE, "
        "SHORT or UNSIGNED_SHORT, got VEC3 of UNSIGNED_INT");
    // KHR_mesh_quantization allows normals of normalized BYTE or SHORT only.
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) { d["accessors"][1]["componentType"] = 5122; }),
        "accessors[1] (NORMAL of meshes[0].primitives[0]) must be VEC3 of FLOAT, or of normalized BYTE or "
        "SHORT, got VEC3 of SHORT");
    EXPECT_CONTAINS_ALL(
        rejectedEdit([](json& d) {
            d["accessors"][0]["sparse"] = {{"count", 1},
                                           {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                           {"values", {{"bufferView", 0}}}};
        }),
        "accessors[0] (POSITION of meshes[0].primitives[0]) is sparse; sparse accessors are not supported");
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["accessors"][0].erase("bufferView"); }),
                        "accessors[0] (POSITION of meshes[0].primitives[0]) has no bufferView");
}

TEST(GltfReject, BrokenGlbContainers) {
    std::string glb = valid().glb();
    EXPECT_CONTAINS_ALL(rejected("a.glb", glb.substr(0, glb.size() - 8)),
                        "a.glb: not a valid .glb: its header says " + std::to_string(glb.size()) +
                            " bytes, but the file has");
    std::string v1 = glb;
    v1[4] = 1;
    EXPECT_CONTAINS_ALL(rejected("a.glb", v1), "a.glb: not a valid .glb: version 1 (only glTF 2.0 binaries");
    EXPECT_CONTAINS_ALL(rejected("a.glb", glb.substr(0, 12)), "a.glb: not a valid .glb: it has 12 bytes");
    std::string longJson = glb;
    longJson[13] = char(0x7f);  // a JSON chunk far longer than the file
    EXPECT_CONTAINS_ALL(rejected("a.glb", longJson), "a.glb: not a valid .glb: its JSON chunk of");
    // A buffer claiming more than the BIN chunk holds.
    GltfBuilder b = valid();
    b.doc["buffers"] = {{{"byteLength", 4000}}};
    std::string claimed = b.glb();
    EXPECT_CONTAINS_ALL(rejected("a.glb", claimed),
                        "a.glb: buffers[0].byteLength: 4000 exceeds the BIN chunk's 80 bytes");
}

TEST(GltfReject, MoreTrianglesThanTheRendererTakesOnceInstancesAreFlattened) {
    // 4096 triangles, placed by 4097 mirroring nodes (flattened, not instanced: instancing.h): 2^24 +
    // 4096 triangles, refused before they are made.
    GltfBuilder b;
    std::vector<glm::vec3> positions;
    for (int t = 0; t < 4096; ++t)
        for (glm::vec3 v : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)})
            positions.push_back(v + glm::vec3(0, 0, float(t)));
    int p = b.vec3(positions);
    b.mesh(json::array({{{"attributes", {{"POSITION", p}}}}}));
    std::vector<int> roots;
    for (int i = 0; i < 4097; ++i) roots.push_back(b.node({{"mesh", 0}, {"scale", {-1, 1, 1}}}));
    b.scene(roots);
    auto start = std::chrono::steady_clock::now();
    EXPECT_CONTAINS_ALL(rejected("many.glb", b.glb()),
                        "many.glb: more than 16777215 triangles once its 4097 mesh instances are flattened");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);

    // Placed without mirroring, the mesh is stored once and instanced: the same 2^24 + 4096 triangles
    // are drawn from 4096 stored.
    for (json& node : b.doc["nodes"]) node.erase("scale");
    test::TempDir dir;
    Scene scene = loadScene(dir.write("many.glb", b.glb()));
    EXPECT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.instances.size(), 4097u);
    EXPECT_EQ(scene.triangleCount(), 4097u * 4096u);
}

TEST(GltfReject, NothingToRender) {
    EXPECT_CONTAINS_ALL(rejectedEdit([](json& d) { d["nodes"][0].erase("mesh"); }),
                        "bad.gltf: no triangles to render (the scene places no mesh)");
    GltfBuilder b = valid();
    b.bin.replace(12, 24, std::string(24, '\0'));  // all three vertices at the origin
    EXPECT_CONTAINS_ALL(
        rejected("bad.gltf", b.gltf()),
        "bad.gltf: no triangles to render (1 degenerate triangle dropped, 0 primitives of points or lines)");
}

}  // namespace
}  // namespace fp
