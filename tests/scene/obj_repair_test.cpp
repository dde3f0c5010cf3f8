// OBJ input that loads, repaired where needed with one warning per kind of repair.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
constexpr double kPi = 3.14159265358979323846;

// Writes `files` (name -> text) to a temporary directory and loads the first as an OBJ, capturing the
// warnings in `capture`.
Scene loadText(const std::string& obj, const std::map<std::string, std::string>& others = {},
               std::string* path = nullptr) {
    test::TempDir dir;
    std::string objPath = dir.write("model.obj", obj);
    for (const auto& [name, text] : others) dir.write(name, text);
    if (path) *path = objPath;
    return loadObj(objPath);
}

float totalArea(const Scene& scene) {
    float area = 0.0f;
    for (const Triangle& t : scene.triangles) area += t.area();
    return area;
}

TEST(ObjRepair, DegenerateTrianglesDropped) {
    WarningCapture capture;
    std::string path;
    Scene scene = loadText(kTriangle +
                               "v 2 2 0\nv 3 3 0\n"  // collinear with vertex 1
                               "f 1 2 3\n"
                               "f 1 4 5\n"   // line 7: collinear
                               "f 2 2 3\n"   // coincident corners
                               "f 1 2 3\n",  // fine
                           {}, &path);
    EXPECT_EQ(scene.triangles.size(), 2u);
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], path, "dropped 2 degenerate", "first at line 7");
}

TEST(ObjRepair, NonFiniteVerticesDropTheirTriangles) {
    WarningCapture capture;
    std::string path;
    Scene scene = loadText(kTriangle +
                               "v nan 0 0\nv 0 inf 0\nv 1e39 0 0\nv 0 0 -INF\n"
                               "f 1 2 3\n"
                               "f 1 2 4\n"  // line 9
                               "f 5 2 3\n"
                               "f 6 2 3 1\n"  // a quad: two triangles
                               "f 1 2 7\n",
                           {}, &path);
    EXPECT_EQ(scene.triangles.size(), 1u);
    EXPECT_TRUE(
        capture.contains("dropped 5 triangles with NaN or infinite vertex coordinates (first at line 9)"))
        << test::joined(capture);
    EXPECT_EQ(capture.messages().size(), 1u) << test::joined(capture);
}

// Finite but huge coordinates (stray vertices at 1e30) overflow the renderer's squared distances and
// the camera that frames them (issue 17: "camera values must be finite numbers" with no camera given):
// their triangles are dropped with a warning, as non-finite ones are, and the rest frames normally.
TEST(ObjRepair, VerticesBeyondTheFloatRangeDropTheirTriangles) {
    WarningCapture capture;
    Scene scene = loadText(kTriangle +
                               "v 1e30 1e30 1e30\nv 2e18 0 0\nv -1e18 0 0\nv 0 -1e18 0\n"
                               "f 1 2 3\n"
                               "f 1 2 4\n"   // line 9: 1e30
                               "f 1 5 3\n"   // 2e18: beyond
                               "f 1 7 6\n",  // -1e18: the limit itself, kept
                           {});
    EXPECT_EQ(scene.triangles.size(), 2u);
    EXPECT_TRUE(capture.contains("dropped 2 triangles with vertex coordinates beyond +-1e18"))
        << test::joined(capture);
    EXPECT_TRUE(capture.contains("first at line 9")) << test::joined(capture);
    Camera framed = frameBounds(scene.bounds(), 40.0f);
    EXPECT_NO_THROW(validateCamera(framed, "camera"));
}

TEST(ObjRepair, ShortFacesSkipped) {
    WarningCapture capture;
    Scene scene = loadText(kTriangle + "f 1 2\nf 1 2 3\nf 3\nf\n");
    EXPECT_EQ(scene.triangles.size(), 1u);
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0],
                        "skipped 3 faces with fewer than 3 vertices (first at line 4)");
}

TEST(ObjRepair, QuadsAndPolygonsTriangulatedKeepingWinding) {
    WarningCapture capture;
    // A unit square (counter-clockwise seen from +z), a regular pentagon, and a concave L-shaped hexagon
    // of area 3 that a plain fan from its first corner would cover wrongly.
    std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    for (int i = 0; i < 5; ++i)
        text += "v " + std::to_string(std::cos(i * 2 * kPi / 5)) + " " +
                std::to_string(std::sin(i * 2 * kPi / 5)) + " 5\n";
    text += "f 5 6 7 8 9\n";
    text += "v 1 0 9\nv 2 0 9\nv 2 2 9\nv 0 2 9\nv 0 1 9\nv 1 1 9\nf 10 11 12 13 14 15\n";
    Scene scene = loadText(text);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);  // polygons are valid OBJ
    ASSERT_EQ(scene.triangles.size(), 2u + 3u + 4u);
    for (const Triangle& t : scene.triangles) {
        EXPECT_GT(t.geometricNormal().z, 0.0f);
        for (const glm::vec3& n : t.n) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    }
    float hexagon = 0.0f;
    for (size_t i = 5; i < 9; ++i) hexagon += scene.triangles[i].area();
    EXPECT_NEAR(hexagon, 3.0f, 1e-5f);
}

TEST(ObjRepair, PolygonWithMoreThan255Corners) {
    // tinyobjloader's LoadObj keeps corner counts in an unsigned char; the streaming reader we use does not.
    std::string text, face = "f";
    const int corners = 1000;
    for (int i = 0; i < corners; ++i) {
        double a = i * 2 * kPi / corners;
        text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
        face += " " + std::to_string(i + 1);
    }
    WarningCapture capture;
    Scene scene = loadText(text + face + "\n");
    EXPECT_EQ(scene.triangles.size(), static_cast<size_t>(corners - 2));
    EXPECT_NEAR(totalArea(scene), kPi, 1e-3);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

TEST(ObjRepair, CollinearCornersInPolygonAddNoSlivers) {
    WarningCapture capture;
    // A square with an extra corner in the middle of its bottom edge, and a repeated corner.
    Scene scene = loadText("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4 4 5\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.triangles.size(), 2u);
    EXPECT_NEAR(totalArea(scene), 4.0f, 1e-6f);
    for (const Triangle& t : scene.triangles) EXPECT_GT(t.area(), 0.5f);
}

TEST(ObjRepair, NormalsFromTheFileAreNormalized) {
    WarningCapture capture;
    Scene scene = loadText(kTriangle + "vn 0 0 5\nvn 3 0 4\nf 1//1 2//2 3//1\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].n[0], glm::vec3(0, 0, 1));
    EXPECT_NEAR(scene.triangles[0].n[1].x, 0.6f, 1e-6f);
    EXPECT_NEAR(scene.triangles[0].n[1].z, 0.8f, 1e-6f);
}

TEST(ObjRepair, ZeroAndNanNormalsUseTheGeometricNormal) {
    WarningCapture capture;
    std::string path;
    // Clockwise seen from +z: the geometric normal is -z.
    Scene scene = loadText(
        "v 0 0 0\nv 0 1 0\nv 1 0 0\nvn 0 0 0\nvn nan 0 1\nvn 0 0 1\n"
        "f 1//3 2//3 3//3\n"
        "f 1//1 2//3 3//3\n"  // line 8
        "f 1//2 2//2 3//2\n",
        {}, &path);
    ASSERT_EQ(scene.triangles.size(), 3u);
    EXPECT_EQ(scene.triangles[1].n[0], glm::vec3(0, 0, -1));
    EXPECT_EQ(scene.triangles[1].n[1], glm::vec3(0, 0, 1));
    for (const glm::vec3& n : scene.triangles[2].n) EXPECT_EQ(n, glm::vec3(0, 0, -1));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], path, "geometric normal", "2 faces", "first at line 8");
}

TEST(ObjRepair, MissingNormalsAreGeometric) {
    Scene scene = loadText("v 0 0 0\nv 0 2 0\nv 2 0 0\nf 1 2 3\n");
    for (const glm::vec3& n : scene.triangles.at(0).n) EXPECT_EQ(n, glm::vec3(0, 0, -1));
}

TEST(ObjRepair, Utf8BomStripped) {
    // tinyobjloader would take "\xEF\xBB\xBFv" for an unknown statement and lose vertex 1.
    WarningCapture capture;
    Scene scene = loadText("\xEF\xBB\xBFv 5 5 5\nv 6 5 5\nv 5 6 5\nf 1 2 3\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].p[0], glm::vec3(5, 5, 5));
}

TEST(ObjRepair, CrlfTabsAndBlanks) {
    WarningCapture capture;
    Scene crlf = loadText("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
    Scene cr = loadText("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
    Scene tabs = loadText("\tv\t0  0\t 0 \nv 1\t0 0\t\n  v 0 1 0\nf\t1   2\t3   \n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    for (const Scene* s : {&crlf, &cr, &tabs}) {
        ASSERT_EQ(s->triangles.size(), 1u);
        EXPECT_EQ(s->triangles[0].p[1], glm::vec3(1, 0, 0));
        EXPECT_EQ(s->triangles[0].p[2], glm::vec3(0, 1, 0));
    }
}

TEST(ObjRepair, VeryLongLines) {
    WarningCapture capture;
    std::string comment = "# " + std::string(2'000'000, 'x') + "\n";
    std::string longVertex = "v 0.000000000000000000000000000000000000000000000000000000000001" +
                             std::string(100'000, ' ') + "0 0\n";
    Scene scene = loadText(comment + longVertex + "v 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.triangles.size(), 1u);
}

TEST(ObjRepair, InlineCommentsAndOtherStatements) {
    // tinyobjloader would read "# quad" as a fourth corner with index 0.
    WarningCapture capture;
    Scene scene =
        loadText("o thing\ng group\ns 1\n" + kTriangle + "vt 0 0\nl 1 2\np 3\nf 1 2 3 # one triangle\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.triangles.size(), 1u);
}

TEST(ObjRepair, IndexForms) {
    Scene scene = loadText(kTriangle +
                           "vt 0 0\nvt 1 0 0\nvn 0 0 1\n"
                           "f 1 2 3\nf 1/1 2/2 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/1/1\n"
                           "f -3 -2 -1\nf +1 +2 +3\nf 1/-1/-1 2 3\n");
    EXPECT_EQ(scene.triangles.size(), 7u);
    for (const Triangle& t : scene.triangles) EXPECT_EQ(t.p[2], glm::vec3(0, 1, 0));
}

TEST(ObjRepair, ForwardReferencesAllowed) {
    // Positive indices may name vertices defined further down, as tinyobjloader allows.
    Scene scene = loadText("f 1 2 3\n" + kTriangle);
    EXPECT_EQ(scene.triangles.size(), 1u);
}

TEST(ObjRepair, VertexColorsAndWAccepted) {
    Scene scene = loadText("v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0 1 0 0 1\nf 1 2 3\n");
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].p[1], glm::vec3(1, 0, 0));
}

TEST(ObjRepair, NumberSpellings) {
    Scene scene = loadText("v +0 -0.0 .0\nv 1. 0e0 0E+0\nv 0 1e-0 -.0\nf 1 2 3\n");
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].p[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.triangles[0].p[2], glm::vec3(0, 1, 0));
}

TEST(ObjRepair, WarningsAreAggregated) {
    // A million-triangle mesh of bad triangles should give one warning per kind, not a million.
    std::string text = "v 0 0 0\nv 1 1 1\nv 2 2 2\nv nan 0 0\n" + kTriangle;
    for (int i = 0; i < 500; ++i) text += "f 1 2 3\nf 4 5 6\nf 1 2\n";
    text += "f 5 6 7\n";
    WarningCapture capture;
    Scene scene = loadText(text);
    EXPECT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(capture.messages().size(), 3u) << test::joined(capture);
    EXPECT_TRUE(capture.contains("dropped 500 degenerate (zero-area) triangles (first at line 8)"));
    EXPECT_TRUE(
        capture.contains("dropped 500 triangles with NaN or infinite vertex coordinates (first at line 9)"));
    EXPECT_TRUE(capture.contains("skipped 500 faces with fewer than 3 vertices (first at line 10)"));
}

}  // namespace
}  // namespace fp
