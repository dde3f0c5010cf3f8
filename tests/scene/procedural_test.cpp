// The benchmark scenes made in code: the exact triangle counts they promise (the suite reports them
// as facts), well-formed geometry, a light, and the same scene for the same seed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/procedural.h"

namespace fp {
namespace {

// Every triangle has area, finite unit normals and a material; the scene has a light facing into the
// room and stays inside the room.
void expectWellFormed(const Scene& scene) {
    ASSERT_FALSE(scene.materials.empty());
    ASSERT_TRUE(scene.camera.has_value());
    size_t emitters = 0, bad = 0;
    for (const Triangle& t : scene.triangles) {
        glm::vec3 g = t.geometricNormal();
        bool ok = t.area() > 0.0f && std::isfinite(t.area()) && t.material < scene.materials.size();
        for (int k = 0; k < 3; ++k) {
            ok = ok && std::isfinite(t.p[k].x) && std::isfinite(t.p[k].y) && std::isfinite(t.p[k].z);
            ok = ok && std::abs(glm::length(t.n[k]) - 1.0f) < 1e-4f;
            // Inside the 2 x 2 x 2 room (with room for float rounding).
            ok = ok && glm::all(glm::greaterThanEqual(t.p[k], glm::vec3(-1e-5f))) &&
                 glm::all(glm::lessThanEqual(t.p[k], glm::vec3(2.0f + 1e-5f)));
        }
        if (!ok && ++bad <= 5) ADD_FAILURE() << "bad triangle " << (&t - scene.triangles.data());
        if (scene.materials[t.material].isEmissive()) {
            ++emitters;
            EXPECT_LT(g.y, 0.0f) << "the light is one-sided and must face down into the room";
        }
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_GE(emitters, 1u);
}

// The floor (every triangle with all three vertices at y = 0) tiles the 2 x 2 square: no gap, no overlap.
float floorArea(const Scene& scene) {
    float area = 0.0f;
    for (const Triangle& t : scene.triangles)
        if (t.p[0].y == 0.0f && t.p[1].y == 0.0f && t.p[2].y == 0.0f) {
            EXPECT_GT(t.geometricNormal().y, 0.0f) << "the floor faces up";
            area += t.area();
        }
    return area;
}

TEST(SphereScene, HasExactlyTheTrianglesItPromises) {
    // The suite's sizes, the smallest possible, odd counts and primes (no rings x segments product).
    for (int n : {18, 19, 20, 33, 101, 1000, 1001, 4099, 65537, 100000, 1000000}) {
        SphereSceneLayout layout = sphereSceneLayout(n);
        EXPECT_EQ(layout.sphereTriangles, 2 * layout.segments * (layout.rings - 1)) << n;
        EXPECT_GE(layout.floorTriangles, 2) << n;
        EXPECT_EQ(kRoomTriangles + layout.floorTriangles + layout.sphereTriangles, n) << n;
        Scene scene = benchmarkSphereScene(n);
        ASSERT_EQ(scene.triangles.size(), size_t(n));
        expectWellFormed(scene);
        EXPECT_NEAR(floorArea(scene), 4.0f, 1e-4f) << n;
    }
}

TEST(SphereScene, TheSphereTakesNearlyEverythingWithSquarishQuads) {
    for (int n : {1000, 100000, 1000000}) {
        SphereSceneLayout layout = sphereSceneLayout(n);
        double aspect = double(layout.segments) / (layout.rings - 1);
        EXPECT_GE(aspect, 1.0) << n;
        EXPECT_LE(aspect, 4.0) << n;
        EXPECT_LE(layout.floorTriangles, 2 + n / 1000) << n;
    }
    EXPECT_EQ(sphereSceneLayout(1000).floorTriangles, 2);  // 988 = 2 * 38 * 13
}

TEST(SphereScene, TooFewTrianglesIsAnError) {
    EXPECT_THROW(sphereSceneLayout(kMinSphereSceneTriangles - 1), Error);
    EXPECT_THROW(benchmarkSphereScene(0), Error);
    EXPECT_EQ(benchmarkSphereScene(kMinSphereSceneTriangles).triangles.size(),
              size_t(kMinSphereSceneTriangles));
}

TEST(TriangleSoup, HasExactlyTheTrianglesItPromises) {
    for (int n : {kMinSoupTriangles, 14, 1000, 100000}) {
        Scene scene = randomTriangleSoup(n, 1);
        ASSERT_EQ(scene.triangles.size(), size_t(n));
        expectWellFormed(scene);
        EXPECT_NEAR(floorArea(scene), 4.0f, 1e-4f);
    }
    EXPECT_THROW(randomTriangleSoup(kMinSoupTriangles - 1, 1), Error);
}

bool sameGeometry(const Scene& a, const Scene& b) {
    if (a.triangles.size() != b.triangles.size()) return false;
    for (size_t i = 0; i < a.triangles.size(); ++i)
        if (a.triangles[i].p != b.triangles[i].p) return false;
    return true;
}

TEST(TriangleSoup, TheSeedDecidesTheScene) {
    EXPECT_TRUE(sameGeometry(randomTriangleSoup(2000, 7), randomTriangleSoup(2000, 7)));
    EXPECT_FALSE(sameGeometry(randomTriangleSoup(2000, 7), randomTriangleSoup(2000, 8)));
    // The generator is defined by its arithmetic, not by the standard library, so this vertex is the same
    // on every platform; a change here changes the benchmark scene.
    Scene scene = randomTriangleSoup(kMinSoupTriangles, 1);
    const glm::vec3& p = scene.triangles.back().p[0];
    EXPECT_TRUE(std::isfinite(p.x) && p.x > 0.3f && p.x < 1.7f);
    EXPECT_EQ(p, randomTriangleSoup(kMinSoupTriangles, 1).triangles.back().p[0]);
}

TEST(TriangleSoup, TrianglesOverlapAsAWorstCaseShould) {
    // Most triangles' bounds overlap others': the mean number of other boxes containing a triangle's
    // centroid, over a sample, is well above one.
    Scene scene = randomTriangleSoup(20000, 3);
    size_t first = scene.triangles.size() - 19988, covered = 0, samples = 200;
    for (size_t i = 0; i < samples; ++i) {
        const Triangle& t = scene.triangles[first + i * 97];
        glm::vec3 c = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        for (size_t j = first; j < scene.triangles.size(); ++j) {
            Aabb b = scene.triangles[j].bounds();
            if (&scene.triangles[j] != &t && glm::all(glm::greaterThanEqual(c, b.lo)) &&
                glm::all(glm::lessThanEqual(c, b.hi)))
                ++covered;
        }
    }
    EXPECT_GT(double(covered) / samples, 2.0);
}

const char* kTetrahedronModule =
    "exports.positions=[[0,1,0],[1,1,0],[0,2,0],[0,1,1],[5,5,5]];\n"
    "exports.cells=[[0,2,1],[0,1,3],[0,3,2],[1,2,3],[4,4,4]];\n";

TEST(MeshModule, ReadsTheNpmMeshLayoutAndJson) {
    IndexedMesh mesh = parseMeshModule(kTetrahedronModule, "tetra.js");
    ASSERT_EQ(mesh.positions.size(), 5u);
    ASSERT_EQ(mesh.cells.size(), 5u);
    EXPECT_EQ(mesh.positions[3], glm::vec3(0, 1, 1));
    EXPECT_EQ(mesh.cells[1], (std::array<uint32_t, 3>{0, 1, 3}));
    IndexedMesh json =
        parseMeshModule(" {\"positions\": [[0,0,0],[1,0,0],[0,1,0]], \"cells\": [[0,1,2]]}", "tri.json");
    EXPECT_EQ(json.positions.size(), 3u);
    EXPECT_EQ(json.cells.size(), 1u);
}

TEST(MeshModule, RejectsWhatIsNotAMesh) {
    struct Case {
        const char* text;
        const char* fragment;
    };
    for (const Case& c :
         {Case{"exports.positions=[[0,0,0]];", "no exports.cells"},
          Case{"exports.positions=[[0,0,0]]; exports.cells=[[0,0,1]];", "indexes no position"},
          Case{"exports.positions=[[0,0]]; exports.cells=[];", "not three numbers"},
          Case{"exports.positions=[[0,0,0]; exports.cells=[];", "tetra.js"},
          Case{"exports.positions=[[0,0,0],[1,0,0],[0,1,0]]; exports.cells=[[0,1,2]", "never ends"},
          Case{"{\"positions\": []}", "\"cells\""}}) {
        try {
            parseMeshModule(c.text, "tetra.js");
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << e.what();
        }
    }
}

TEST(MeshScene, StandsTheMeshInTheRoomAndDropsCellsWithoutArea) {
    Scene scene = benchmarkMeshScene(parseMeshModule(kTetrahedronModule, "tetra.js"), "tetrahedron");
    // The room with a one-quad floor, and four of the five cells: [4,4,4] has no area.
    ASSERT_EQ(scene.triangles.size(), size_t(kRoomTriangles + 2 + 4));
    expectWellFormed(scene);
    Aabb mesh;
    for (size_t i = kRoomTriangles + 2; i < scene.triangles.size(); ++i)
        mesh.grow(scene.triangles[i].bounds());
    EXPECT_NEAR(mesh.lo.y, 0.0f, 1e-6f) << "on the floor";
    EXPECT_NEAR(std::max({mesh.extent().x, mesh.extent().y, mesh.extent().z}), 1.2f, 1e-5f);
    EXPECT_NEAR(mesh.center().x, 1.0f, 1e-5f);
    EXPECT_NEAR(mesh.center().z, 1.0f, 1e-5f);
    EXPECT_THROW(benchmarkMeshScene(
                     parseMeshModule("exports.positions=[[0,0,0]];exports.cells=[[0,0,0]];", "dot"), "dot"),
                 Error);
}

}  // namespace
}  // namespace fp
