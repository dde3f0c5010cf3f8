// Materials: MTL libraries next to the OBJ, their repairs, and the default material.
#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene/mtl.h"
#include "scene_test_util.h"

namespace fp {
namespace {

const std::string kTwoTriangles = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";

// Loads an OBJ using material `use` from `mtl` (written as lib.mtl next to it).
struct Loaded {
    Scene scene;
    std::string objPath, mtlPath;
};
Loaded loadWithMtl(const std::string& mtl, const std::string& faces = "usemtl m\nf 1 2 3\n") {
    test::TempDir dir;
    Loaded out;
    out.objPath = dir.write("model.obj", "mtllib lib.mtl\n" + kTwoTriangles + faces);
    out.mtlPath = dir.write("lib.mtl", mtl);
    out.scene = loadObj(out.objPath);
    return out;
}

const Material& only(const Scene& scene) {
    EXPECT_EQ(scene.materials.size(), 1u);
    return scene.materials.at(0);
}

TEST(Mtl, DiffuseAndEmission) {
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl m\nKd 0.25 0.5 0.75\nKe 1 2 30\nKs 1 1 1\nNs 10\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    const Material& m = only(l.scene);
    EXPECT_EQ(m.name, "m");
    EXPECT_EQ(m.diffuse, glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(m.emission, glm::vec3(1.0f, 2.0f, 30.0f));
    EXPECT_EQ(l.scene.triangles.at(0).material, 0u);
}

TEST(Mtl, SingleValueKdIsGrey) {
    // The MTL spec's "Kd 0.14" is grey; tinyobjloader alone reads (0.14, 0, 0).
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl m\nKd 0.14\nKe 2\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(only(l.scene).diffuse, glm::vec3(0.14f));
    EXPECT_EQ(only(l.scene).emission, glm::vec3(2.0f));
}

TEST(Mtl, KdClampedToUnitRange) {
    WarningCapture capture;
    Loaded l = loadWithMtl("# comment\nnewmtl m\nKd 1.5 -0.25 0.5\n");
    EXPECT_EQ(only(l.scene).diffuse, glm::vec3(1.0f, 0.0f, 0.5f));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], l.mtlPath, "clamped 2 Kd values to [0, 1] (first at line 3)");
}

TEST(Mtl, NanAndInfinityReplacedByZero) {
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl m\nKd nan 0.5 0.5\nKe inf 1 1e39\n");
    EXPECT_EQ(only(l.scene).diffuse, glm::vec3(0.0f, 0.5f, 0.5f));
    EXPECT_EQ(only(l.scene).emission, glm::vec3(0.0f, 1.0f, 0.0f));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], l.mtlPath, "replaced 3 NaN or infinite", "first at line 2");
}

TEST(Mtl, NegativeEmissionClamped) {
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl m\nKe -1 5 -2\n");
    EXPECT_EQ(only(l.scene).emission, glm::vec3(0.0f, 5.0f, 0.0f));
    EXPECT_TRUE(capture.contains("set 2 negative Ke values to 0 (first at line 2)")) << test::joined(capture);
}

TEST(Mtl, MalformedAndUnsupportedColorsIgnored) {
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl m\nKd 0.5 abc 0.2\nKe 0.1 0.2\nKe spectral light.spd\nKd xyz 1 1 1\n");
    // A material without a usable Kd keeps tinyobjloader's 0.
    EXPECT_EQ(only(l.scene).diffuse, glm::vec3(0.0f));
    EXPECT_EQ(only(l.scene).emission, glm::vec3(0.0f));
    EXPECT_EQ(capture.messages().size(), 2u) << test::joined(capture);
    EXPECT_TRUE(capture.contains("ignored 2 malformed Kd/Ke statements (first at line 2)"))
        << test::joined(capture);
    // The warnings name the statements in the order they first needed the repair.
    EXPECT_TRUE(capture.contains("ignored 2 spectral or CIE XYZ Ke/Kd statements")) << test::joined(capture);
}

TEST(Mtl, MissingLibraryGivesDefaultMaterial) {
    test::TempDir dir;
    std::string obj =
        dir.write("model.obj", "# header\nmtllib nowhere.mtl\n" + kTwoTriangles + "usemtl red\nf 1 2 3\n");
    WarningCapture capture;
    Scene scene = loadObj(obj);
    const Material& m = only(scene);
    EXPECT_EQ(m.diffuse, glm::vec3(0.8f));
    EXPECT_EQ(m.emission, glm::vec3(0.0f));
    EXPECT_EQ(capture.messages().size(), 2u) << test::joined(capture);
    EXPECT_TRUE(capture.contains("material library 'nowhere.mtl' not found (first at line 2)"))
        << test::joined(capture);
    EXPECT_TRUE(capture.contains("undefined material 'red'")) << test::joined(capture);
}

TEST(Mtl, UndefinedMaterialGetsDefault) {
    WarningCapture capture;
    Loaded l = loadWithMtl("newmtl white\nKd 1 1 1\n",
                           "usemtl white\nf 1 2 3\nusemtl purple\nf 2 4 3\nf 1 2 4\nusemtl white\nf 1 2 3\n");
    ASSERT_EQ(l.scene.materials.size(), 2u);
    EXPECT_EQ(l.scene.materials[1].name, "default");
    EXPECT_EQ(l.scene.materials[1].diffuse, glm::vec3(0.8f));
    std::vector<uint32_t> used;
    for (const Triangle& t : l.scene.triangles) used.push_back(t.material);
    EXPECT_EQ(used, (std::vector<uint32_t>{0, 1, 1, 0}));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], l.objPath, "gave 2 faces the default material",
                        "undefined material 'purple'", "first at line 9");
}

TEST(Mtl, NoUsemtlMeansDefaultWithoutWarning) {
    test::TempDir dir;
    WarningCapture capture;
    Scene scene = loadObj(dir.write("plain.obj", kTwoTriangles + "f 1 2 3\n"));
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(only(scene).name, "default");
}

TEST(Mtl, NamesWithBlanksAndBom) {
    // "newmtl  wall paint " would be named " wall paint" by tinyobjloader; both sides are trimmed.
    WarningCapture capture;
    Loaded l = loadWithMtl("\xEF\xBB\xBFnewmtl  wall paint \r\nKd\t0.5 0.5 0.5\r\n",
                           "usemtl wall paint  \nf 1 2 3\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(only(l.scene).name, "wall paint");
    EXPECT_EQ(only(l.scene).diffuse, glm::vec3(0.5f));
}

TEST(Mtl, SeveralLibrariesAndFileNamesWithBlanks) {
    test::TempDir dir;
    dir.write("a.mtl", "newmtl a\nKd 0.1 0.1 0.1\n");
    dir.write("b.mtl", "newmtl b\nKd 0.2 0.2 0.2\n");
    dir.write("my materials.mtl", "newmtl c\nKd 0.3 0.3 0.3\n");
    std::string obj = dir.write("model.obj", "mtllib a.mtl b.mtl\nmtllib my materials.mtl\nmtllib a.mtl\n" +
                                                 kTwoTriangles + "usemtl c\nf 1 2 3\nusemtl a\nf 2 4 3\n");
    WarningCapture capture;
    Scene scene = loadObj(obj);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[scene.triangles[0].material].diffuse, glm::vec3(0.3f));
    EXPECT_EQ(scene.materials[scene.triangles[1].material].diffuse, glm::vec3(0.1f));
}

TEST(Mtl, BinaryOrEmptyLibraryIgnored) {
    WarningCapture capture;
    Loaded binary = loadWithMtl(std::string("newmtl m\0\0\0", 11));
    EXPECT_EQ(only(binary.scene).name, "default");
    EXPECT_TRUE(capture.contains(binary.mtlPath + ": contains binary data")) << test::joined(capture);
    Loaded empty = loadWithMtl("");
    EXPECT_EQ(only(empty.scene).name, "default");
    EXPECT_TRUE(capture.contains(empty.mtlPath + ": defines no materials")) << test::joined(capture);
}

TEST(Mtl, FirstDefinitionWins) {
    Loaded l = loadWithMtl("newmtl m\nKd 0.1 0.1 0.1\nnewmtl m\nKd 0.9 0.9 0.9\n");
    EXPECT_EQ(l.scene.materials.at(l.scene.triangles.at(0).material).diffuse, glm::vec3(0.1f));
}

TEST(Mtl, SanitizeKeepsLinesAndRespellsColors) {
    WarningCapture capture;
    std::string clean = sanitizeMtl("newmtl   x  \r\nKd 0.5\nKa 1 2\n# Kd 7\nKe 1 -1 2\n", "t.mtl");
    EXPECT_EQ(clean, "newmtl x\nKd 0.5 0.5 0.5\nKa 1 2\n# Kd 7\nKe 1 0 2\n");
}

}  // namespace
}  // namespace fp
