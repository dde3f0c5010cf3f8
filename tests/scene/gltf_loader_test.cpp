// glTF geometry: files the tests write (JSON with data-URI or external buffers, and .glb), checked
// against the transforms, winding, normals, texture coordinates and camera worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_util.h"
#include "scene/instancing.h"
#include "scene/load.h"
#include "scene/scene_file.h"
#include "scene_test_util.h"
#include "texture_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::GltfBuilder;

const std::vector<uint8_t> kTexels = test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255});

Scene loadFile(const std::string& name, const std::string& bytes) {
    test::TempDir dir;
    return loadScene(dir.write(name, bytes));
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

// A unit cube centred at the origin: four vertices per face (normal, uv (0,0) (1,0) (1,1) (0,1) in glTF's
// convention, v = 0 at the top of the image), two triangles per face, counter-clockwise from outside.
struct Box {
    std::vector<glm::vec3> p, n;
    std::vector<glm::vec2> uv;
    std::vector<uint16_t> indices;
    Box() {
        const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const glm::vec3& normal : axes) {
            glm::vec3 u = std::abs(normal.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
            glm::vec3 v = glm::cross(normal, u);  // u x v = normal
            uint16_t first = uint16_t(p.size());
            glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (const glm::vec2& c : corners) {
                p.push_back(0.5f * (normal + c.x * u + c.y * v));
                n.push_back(normal);
                uv.push_back(0.5f * (c + 1.0f));
            }
            for (uint16_t k : {0, 1, 2, 0, 2, 3}) indices.push_back(uint16_t(first + k));
        }
    }
};

// The textured box, its image in a data URI (.gltf) or in a buffer view (.glb).
GltfBuilder texturedBox(bool imageInBuffer) {
    GltfBuilder b;
    Box box;
    json attributes = {
        {"POSITION", b.vec3(box.p)}, {"NORMAL", b.vec3(box.n)}, {"TEXCOORD_0", b.vec2(box.uv)}};
    int indices = b.indices16(box.indices);
    std::string png = test::pngBytes(2, 2, kTexels);
    json image = imageInBuffer ? json{{"bufferView", b.view(png)}, {"mimeType", "image/png"}}
                               : json{{"uri", "data:image/png;base64," + test::base64(png)}};
    b.push("images", image);
    b.push("textures", {{"source", 0}});
    b.material({{"name", "checker"},
                {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}}}});
    b.mesh(json::array({{{"attributes", attributes}, {"indices", indices}, {"material", 0}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    return b;
}

TEST(GltfLoader, TexturedBoxFromDataUris) {
    WarningCapture capture;
    Scene scene = loadFile("box.gltf", texturedBox(false).gltf());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.triangles.size(), 12u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].image.width, 2);
    EXPECT_EQ(scene.textures[0].image.texels, kTexels);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].name, "checker");
    EXPECT_EQ(scene.materials[0].type, MaterialType::MetallicRoughness);
    EXPECT_EQ(scene.materials[0].diffuseTexture, 0);
    EXPECT_FALSE(scene.camera.has_value());
    Box box;
    for (size_t t = 0; t < 12; ++t) {
        const Triangle& tri = scene.triangles[t];
        size_t face = t / 2;
        glm::vec3 normal = box.n[face * 4];
        // Counter-clockwise from outside: the geometric normal is the file's.
        expectNear(glm::normalize(tri.geometricNormal()), normal);
        for (int k = 0; k < 3; ++k) {
            uint16_t vertex = box.indices[t * 3 + size_t(k)];
            EXPECT_EQ(tri.p[k], box.p[vertex]);
            EXPECT_EQ(tri.n[k], normal);
            // glTF's (u, v) with v down the image is our (u, 1 - v).
            EXPECT_EQ(tri.uv[k], glm::vec2(box.uv[vertex].x, 1.0f - box.uv[vertex].y));
        }
    }
    // The first corner of the first face: glTF uv (0, 0), the image's top-left texel, is our v = 1.
    EXPECT_EQ(scene.triangles[0].uv[0], glm::vec2(0.0f, 1.0f));
}

TEST(GltfLoader, GlbHoldsTheSameScene) {
    Scene gltf = loadFile("box.gltf", texturedBox(false).gltf());
    WarningCapture capture;
    Scene glb = loadFile("box.glb", texturedBox(true).glb());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(glb.triangles.size(), gltf.triangles.size());
    for (size_t t = 0; t < glb.triangles.size(); ++t) {
        EXPECT_EQ(glb.triangles[t].p, gltf.triangles[t].p);
        EXPECT_EQ(glb.triangles[t].n, gltf.triangles[t].n);
        EXPECT_EQ(glb.triangles[t].uv, gltf.triangles[t].uv);
    }
    ASSERT_EQ(glb.textures.size(), 1u);
    EXPECT_EQ(glb.textures[0].image.texels, kTexels);
}

TEST(GltfLoader, ExternalBufferAndImageFilesAreRelativeToTheGltf) {
    GltfBuilder b = texturedBox(false);
    b.doc["images"][0] = {{"uri", "tex%20maps/checker.png"}};  // percent-encoded, as URIs are
    test::TempDir dir;
    dir.write("model/data.bin", b.bin);
    dir.write("model/tex maps/checker.png", test::pngBytes(2, 2, kTexels));
    Scene scene = loadScene(dir.write("model/box.gltf", b.gltf("data.bin")));
    EXPECT_EQ(scene.triangles.size(), 12u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].image.texels, kTexels);

    // Two buffers may name the same file: the indices read from the second.
    json doc = json::parse(b.gltf("data.bin"));
    doc["buffers"].push_back(doc["buffers"][0]);
    doc["bufferViews"][3]["buffer"] = 1;
    Scene twice = loadScene(dir.write("model/twice.gltf", doc.dump()));
    ASSERT_EQ(twice.triangles.size(), 12u);
    EXPECT_EQ(twice.triangles[11].p, scene.triangles[11].p);
}

// One triangle in z = 0 with +z normals.
int triangleMesh(GltfBuilder& b) {
    int p = b.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    int n = b.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    return b.mesh(json::array({{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}}}));
}

TEST(GltfLoader, NodeHierarchyWithTrsAndMatrix) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    // A triangle in the plane x + y = 0 (normal (1, 1, 0) / sqrt 2), for a non-uniform scale.
    int slanted = b.mesh(json::array(
        {{{"attributes",
           {{"POSITION", b.vec3({{0, 0, 0}, {0, 0, 1}, {1, -1, 0}})},
            {"NORMAL", b.vec3(std::vector<glm::vec3>(3, glm::normalize(glm::vec3(1, 1, 0))))}}}}}));
    double s = std::sqrt(0.5);
    b.node(
        {{"translation", {1, 2, 3}}, {"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}, {"children", {1, 2}}});
    b.node({{"mesh", tri}, {"translation", {0, 0, 5}}});
    // Mirrors x and moves by 10 along x, as a column-major matrix.
    b.node({{"mesh", tri}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}});
    b.node({{"mesh", triangleMesh(b)}});  // a mesh of its own: one used twice would be instanced
    b.node({{"mesh", slanted}, {"scale", {1, 2, 1}}});
    b.scene({0, 3, 4});
    WarningCapture capture;
    Scene scene = loadFile("tree.gltf", b.gltf());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.triangles.size(), 4u);  // depth first: nodes 1, 2, 3, 4

    // The root: scale 2, then 90 degrees about +z ((x, y) -> (-y, x)), then move by (1, 2, 3).
    auto root = [](glm::vec3 p) { return glm::vec3(-2 * p.y, 2 * p.x, 2 * p.z) + glm::vec3(1, 2, 3); };
    const glm::vec3 local[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Triangle& child = scene.triangles[0];
    for (int k = 0; k < 3; ++k) expectNear(child.p[k], root(local[k] + glm::vec3(0, 0, 5)));
    for (int k = 0; k < 3; ++k) expectNear(child.n[k], glm::vec3(0, 0, 1));

    // The mirror reverses the winding: corners 1 and 2 swap, so the front stays where the normal points.
    const Triangle& mirrored = scene.triangles[1];
    auto mirror = [&](glm::vec3 p) { return root(glm::vec3(10 - p.x, p.y, p.z)); };
    expectNear(mirrored.p[0], mirror(local[0]));
    expectNear(mirrored.p[1], mirror(local[2]));
    expectNear(mirrored.p[2], mirror(local[1]));
    for (int k = 0; k < 3; ++k) expectNear(mirrored.n[k], glm::vec3(0, 0, 1));
    expectNear(glm::normalize(mirrored.geometricNormal()), glm::vec3(0, 0, 1));

    for (int k = 0; k < 3; ++k) EXPECT_EQ(scene.triangles[2].p[k], local[k]);  // a root without a transform

    // Normals go through the inverse transpose: (1, 1, 0) under scale (1, 2, 1) is (2, 1, 0), the
    // normal of the scaled triangle.
    const Triangle& scaled = scene.triangles[3];
    expectNear(scaled.p[2], glm::vec3(1, -2, 0));
    glm::vec3 expected = glm::normalize(glm::vec3(2, 1, 0));
    for (int k = 0; k < 3; ++k) expectNear(scaled.n[k], expected);
    expectNear(glm::normalize(scaled.geometricNormal()), expected);
}

TEST(GltfLoader, NonIndexedStripAndFanPrimitives) {
    GltfBuilder b;
    std::vector<glm::vec3> zigzag = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    std::vector<glm::vec3> fan = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {-1, 1, 1}};
    std::vector<glm::vec3> soup = {{0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {5, 0, 2}, {6, 0, 2}, {5, 1, 2}};
    int strip = b.vec3(zigzag), fanned = b.vec3(fan), listed = b.vec3(soup);
    // A strip with a repeated index (joining two strips): its zero-area triangles vanish silently.
    int joined = b.indices16({0, 1, 2, 2, 3, 4});
    b.mesh(json::array({{{"attributes", {{"POSITION", strip}}}, {"mode", 5}},
                        {{"attributes", {{"POSITION", fanned}}}, {"mode", 6}},
                        {{"attributes", {{"POSITION", listed}}}},
                        {{"attributes", {{"POSITION", strip}}}, {"mode", 5}, {"indices", joined}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    WarningCapture capture;
    Scene scene = loadFile("modes.gltf", b.gltf());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    // The glTF specification's orders: strip triangle i is (i, i + 1 + i % 2, i + 2 - i % 2), fan
    // triangle i is (i + 1, i + 2, 0).
    std::vector<std::array<glm::vec3, 3>> expected = {
        {zigzag[0], zigzag[1], zigzag[2]},
        {zigzag[1], zigzag[3], zigzag[2]},
        {zigzag[2], zigzag[3], zigzag[4]},
        {fan[1], fan[2], fan[0]},
        {fan[2], fan[3], fan[0]},
        {fan[3], fan[4], fan[0]},
        {soup[0], soup[1], soup[2]},
        {soup[3], soup[4], soup[5]},
        // Indices 0 1 2 2 3 4: triangles (0 1 2), (1 2 2), (2 2 3) and (2 4 3) (odd, so its last two
        // swap); the middle two repeat a vertex.
        {zigzag[0], zigzag[1], zigzag[2]},
        {zigzag[2], zigzag[4], zigzag[3]}};
    ASSERT_EQ(scene.triangles.size(), expected.size());
    for (size_t t = 0; t < expected.size(); ++t) {
        EXPECT_EQ(scene.triangles[t].p, expected[t]) << "triangle " << t;
        // No NORMAL: the geometric normal, and every strip and fan triangle winds the same way.
        glm::vec3 geometric = glm::normalize(scene.triangles[t].geometricNormal());
        for (int k = 0; k < 3; ++k) expectNear(scene.triangles[t].n[k], geometric);
    }
    for (size_t t = 0; t < 3; ++t) expectNear(scene.triangles[t].n[0], glm::vec3(0, 0, -1));
    for (size_t t = 3; t < 6; ++t) expectNear(scene.triangles[t].n[0], glm::vec3(0, 0, 1));
}

TEST(GltfLoader, PointsAndLinesAreSkippedWithOneWarning) {
    GltfBuilder b;
    int p = b.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    b.mesh(json::array({{{"attributes", {{"POSITION", p}}}},
                        {{"attributes", {{"POSITION", p}}}, {"mode", 0}},
                        {{"attributes", {{"POSITION", p}}}, {"mode", 1}},
                        {{"attributes", {{"POSITION", p}}}, {"mode", 3}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    WarningCapture capture;
    Scene scene = loadFile("lines.gltf", b.gltf());
    EXPECT_EQ(scene.triangles.size(), 1u);
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "lines.gltf: skipped 3 primitives of points or lines");
}

TEST(GltfLoader, DefaultSceneAndMeshesUsedTwice) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    b.node({{"mesh", tri}});
    b.node({{"mesh", tri}, {"translation", {0, 0, 7}}});
    b.node({{"mesh", tri}, {"translation", {0, 0, 9}}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1, 2}}}});
    b.doc["scene"] = 1;
    Scene scene = loadFile("scenes.gltf", b.gltf());
    // Scene 1 only, its mesh placed twice: stored once and instanced (scene/instancing.h).
    EXPECT_TRUE(scene.triangles.empty());
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    scene = flattenInstances(scene);
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].p[0], glm::vec3(0, 0, 7));
    EXPECT_EQ(scene.triangles[1].p[0], glm::vec3(0, 0, 9));
    b.doc.erase("scene");  // without "scene", the first
    scene = loadFile("scenes.gltf", b.gltf());
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].p[0], glm::vec3(0, 0, 0));
}

TEST(GltfLoader, FirstPerspectiveCameraFromItsNodesWorldTransform) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    double s = std::sqrt(0.5);
    b.push("cameras", {{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 100}}}});
    b.push("cameras",
           {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 1.5}}}});
    b.push("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}});
    // The triangle's bounding box is centred at (-5, 2.5, 13) once moved.
    b.node({{"mesh", tri}, {"translation", {-5.5, 2, 13}}});
    b.node({{"translation", {0, 0, 10}}, {"children", {2, 3, 4}}});
    b.node({{"camera", 0}});
    // Turned 90 degrees about +y, it looks along -x ((0, 0, -1) -> (-1, 0, 0)).
    b.node({{"camera", 1}, {"translation", {1, 2, 3}}, {"rotation", {0, s, 0, s}}});
    b.node({{"camera", 2}});
    b.scene({0, 1});
    WarningCapture capture;
    Scene scene = loadFile("camera.gltf", b.gltf());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_TRUE(scene.camera.has_value());
    const Camera& c = *scene.camera;
    expectNear(c.eye, glm::vec3(1, 2, 13));
    expectNear(glm::normalize(c.target - c.eye), glm::vec3(-1, 0, 0));
    expectNear(c.up, glm::vec3(0, 1, 0));
    EXPECT_NEAR(c.fovY, 0.5 * 180.0 / 3.14159265358979323846, 1e-4);
    // The target is on the view axis at the depth of the scene's centre, 6 ahead.
    expectNear(c.target, glm::vec3(-5, 2, 13));

    // A scene file without a camera keeps the glTF's; with one, its own wins.
    test::TempDir dir;
    dir.write("camera.gltf", b.gltf());
    Scene viaFile = loadScene(dir.write("a.json", R"({"mesh": "camera.gltf"})"));
    ASSERT_TRUE(viaFile.camera.has_value());
    EXPECT_EQ(viaFile.camera->eye, c.eye);
    viaFile = loadScene(dir.write(
        "b.json", R"({"mesh": "camera.gltf", "camera": {"eye": [0, 0, 50], "target": [0, 0, 0]}})"));
    EXPECT_EQ(viaFile.camera->eye, glm::vec3(0, 0, 50));
}

TEST(GltfLoader, OrthographicCamerasAloneAreIgnoredWithAWarning) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    b.push("cameras", {{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 100}}}});
    b.node({{"mesh", tri}, {"camera", 0}});
    b.scene({0});
    WarningCapture capture;
    Scene scene = loadFile("ortho.glb", b.glb());
    EXPECT_FALSE(scene.camera.has_value());
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "ortho.glb: orthographic cameras not supported");
}

// KHR_lights_punctual lights arrive as the scene's punctual lights, placed by their nodes: the position
// is the node's origin, the direction its -Z axis, colour x intensity 1:1 (scene/scene.h PunctualLight).
TEST(GltfLoader, PunctualLightsArePlacedByTheirNodes) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_iridescence"};
    b.doc["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights",
           {{{"type", "point"}, {"intensity", 10}, {"color", {1.0, 0.5, 0.25}}, {"name", "bulb"}},
            {{"type", "spot"},
             {"intensity", 2},
             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
            {{"type", "directional"}, {"intensity", 3}}}}}}};
    b.node({{"mesh", tri}});
    // A point light moved to (1, 2, 3); a spot turned -90 degrees about +x (its -Z now points down, -y);
    // a directional light under a parent turned 180 degrees about +y (its -Z now +z).
    b.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.node({{"translation", {0, 5, 0}},
            {"rotation", {-0.70710678, 0, 0, 0.70710678}},
            {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    b.node({{"children", {4}}, {"rotation", {0, 1, 0, 0}}});
    b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    b.scene({0, 1, 2, 3});
    WarningCapture capture;
    Scene scene = loadFile("lights.gltf", b.gltf());
    ASSERT_EQ(scene.punctualLights.size(), 3u);
    const PunctualLight& point = scene.punctualLights[0];
    EXPECT_EQ(point.type, PunctualLightType::Point);
    EXPECT_EQ(point.name, "bulb");
    EXPECT_EQ(point.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(point.intensity, glm::vec3(10.0f, 5.0f, 2.5f));
    const PunctualLight& spot = scene.punctualLights[1];
    EXPECT_EQ(spot.type, PunctualLightType::Spot);
    EXPECT_EQ(spot.position, glm::vec3(0, 5, 0));
    EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(spot.direction), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.5f);
    EXPECT_EQ(spot.intensity, glm::vec3(2.0f));
    const PunctualLight& sun = scene.punctualLights[2];
    EXPECT_EQ(sun.type, PunctualLightType::Directional);
    EXPECT_NEAR(sun.direction.z, 1.0f, 1e-6f);
    // Only the extension it does not implement is warned about.
    EXPECT_TRUE(
        capture.contains("ignoring extensions fragpath does not implement: KHR_materials_iridescence"))
        << test::joined(capture);
    EXPECT_EQ(capture.messages().size(), 1u) << test::joined(capture);
}

TEST(GltfLoader, ABadPunctualLightIsAClearError) {
    GltfBuilder b;
    int tri = triangleMesh(b);
    b.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "area"}, {"intensity", 1}}}}}}};
    b.node({{"mesh", tri}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.scene({0});
    try {
        loadFile("bad_light.gltf", b.gltf());
        ADD_FAILURE() << "an area light is no punctual light";
    } catch (const Error& e) {
        EXPECT_CONTAINS_ALL(e.what(), "bad_light.gltf: KHR_lights_punctual light 0: unknown type 'area'");
    }
}

TEST(GltfLoader, UpperCaseFileExtensionAndAFileWithoutScenesRendersEveryRootNode) {
    GltfBuilder b;
    // A mesh each: one mesh under several nodes would be instanced.
    b.node({{"mesh", triangleMesh(b)}, {"children", {1}}});
    b.node({{"mesh", triangleMesh(b)}, {"translation", {0, 0, 1}}});
    b.node({{"mesh", triangleMesh(b)}, {"translation", {0, 0, 2}}});
    WarningCapture capture;
    Scene scene = loadFile("NOSCENE.GLB", b.glb());
    ASSERT_EQ(scene.triangles.size(), 3u);  // roots 0 and 2, and 0's child
    EXPECT_EQ(scene.triangles[1].p[0], glm::vec3(0, 0, 1));
    EXPECT_TRUE(capture.contains("no scenes; rendering all 2 root nodes")) << test::joined(capture);
}

}  // namespace
}  // namespace fp
