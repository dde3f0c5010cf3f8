// Textured OBJ/MTL input: vt statements and their index rules, map_Kd files found relative to the MTL
// library, faces without vt, and every way a texture file can be wrong.
#include <gtest/gtest.h>

#include "image/rgba8_image.h"
#include "image/tone_map.h"
#include "scene/load.h"
#include "scene_test_util.h"
#include "texture_test_util.h"

namespace fp {
namespace {

// A unit quad in z = 0 with vt (0,0) (1,0) (1,1) (0,1) at its corners, material "tex".
const std::string kQuad =
    "mtllib mats/a.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl tex\n";

const std::vector<uint8_t> kTexels = test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255});

// Writes the OBJ, the library mats/a.mtl and the 2x2 checker as mats/tex.png; loads the OBJ.
Scene loadTextured(const std::string& faces, const std::string& mtl = "newmtl tex\nmap_Kd tex.png\n") {
    test::TempDir dir;
    dir.write("mats/a.mtl", mtl);
    dir.write("mats/tex.png", test::pngBytes(2, 2, kTexels));
    return loadObj(dir.write("model.obj", kQuad + faces));
}

TEST(ObjTexture, TexcoordsFollowTheFacesAndTheTextureIsRelativeToTheMtl) {
    WarningCapture capture;
    Scene scene = loadTextured("f 1/1 2/2 3/3\nf 1/1/1 3/3/1 4/4/1\nvn 0 0 1\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.triangles.size(), 2u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].image.width, 2);
    EXPECT_EQ(scene.textures[0].image.height, 2);
    EXPECT_EQ(scene.textures[0].image.texels, kTexels);
    for (const Triangle& t : scene.triangles) {
        EXPECT_EQ(scene.materials[t.material].diffuseTexture, 0);
        EXPECT_EQ(scene.materials[t.material].diffuse, glm::vec3(1.0f));  // no Kd: the texture alone
        // Each corner's vt equals its position's x, y here.
        for (int k = 0; k < 3; ++k) EXPECT_EQ(t.uv[k], glm::vec2(t.p[k])) << k;
    }
}

TEST(ObjTexture, NegativeAndShortTexcoordIndices) {
    // -1 is the latest vt; "vt 0.25" has v = 0 (the OBJ default).
    Scene scene = loadTextured("vt 0.25\nf 1/-5 2/-4 3/-1\n");
    ASSERT_EQ(scene.triangles.size(), 1u);
    const Triangle& t = scene.triangles[0];
    EXPECT_EQ(t.uv[0], glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(t.uv[1], glm::vec2(1.0f, 0.0f));
    EXPECT_EQ(t.uv[2], glm::vec2(0.25f, 0.0f));
}

TEST(ObjTexture, TexcoordIndexOutOfRangeIsRejected) {
    std::string message = test::errorOf([] { loadTextured("f 1/1 2/2 3/9\n"); });
    EXPECT_CONTAINS_ALL(message, "model.obj:", "texture coordinate index 9 out of range");
    message = test::errorOf([] { loadTextured("f 1/-5 2/-4 3/-3\n"); });
    EXPECT_CONTAINS_ALL(message, "model.obj:", "relative texture coordinate index -5");
}

TEST(ObjTexture, FacesWithoutTexcoordsGetTheTexturesMeanColour) {
    WarningCapture capture;
    // Line 11: no vt; line 12: vt on two corners only (invalid OBJ, taken as none); line 13: fine.
    Scene scene =
        loadTextured("f 1 2 3\nf 1/1 3/3 4\nf 1/1 3/3 4/4\n", "newmtl tex\nKd 0.5\nmap_Kd tex.png\n");
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_EQ(capture.messages()[0],
              scene.source +
                  ": gave 2 faces of textured materials without texture coordinates (vt) Kd times the "
                  "texture's mean colour (first at line 11)");
    ASSERT_EQ(scene.triangles.size(), 3u);
    float red = srgbDecode(1.0f);
    glm::vec3 mean = 0.5f * glm::vec3(red, 0.0f, red);  // half the texels red, half blue
    for (int i = 0; i < 2; ++i) {
        const Material& m = scene.materials[scene.triangles[size_t(i)].material];
        EXPECT_EQ(m.diffuseTexture, -1);
        EXPECT_NEAR(m.diffuse.r, 0.5f * mean.r, 1e-6f);
        EXPECT_NEAR(m.diffuse.g, 0.0f, 1e-6f);
        EXPECT_NEAR(m.diffuse.b, 0.5f * mean.b, 1e-6f);
    }
    EXPECT_EQ(scene.triangles[0].material, scene.triangles[1].material) << "one copy per material";
    const Material& textured = scene.materials[scene.triangles[2].material];
    EXPECT_EQ(textured.diffuseTexture, 0);
    EXPECT_EQ(textured.diffuse, glm::vec3(0.5f));
}

// The one warning a broken texture gets, or "" (with a test failure) when there is not exactly one.
std::string onlyWarning(const WarningCapture& capture) {
    EXPECT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    return capture.messages().empty() ? "" : capture.messages()[0];
}

// The material of the first triangle shows the checker in place of its texture, with Kd 1.
void expectChecker(const Scene& scene) {
    ASSERT_FALSE(scene.triangles.empty());
    const Material& m = scene.materials[scene.triangles[0].material];
    ASSERT_GE(m.diffuseTexture, 0);
    EXPECT_EQ(scene.textures[size_t(m.diffuseTexture)].image.texels, missingTextureChecker().texels);
    EXPECT_EQ(m.diffuse, glm::vec3(1.0f));
}

TEST(ObjTexture, MissingTextureWarnsNamingTheMtlLineMaterialAndPathAndShowsTheChecker) {
    test::TempDir dir;
    dir.write("mats/a.mtl", "newmtl tex\nKd 0.2 0.9 0.2\nmap_Kd -s 2 2 missing.png\n");
    std::string obj = dir.write("model.obj", kQuad + "f 1/1 2/2 3/3\n");
    WarningCapture capture;
    Scene scene = loadObj(obj);
    std::string textureWarning;  // the ignored "-s" option gets a warning of its own
    for (const std::string& m : capture.messages())
        if (m.find("material 'tex'") != std::string::npos) textureWarning += m;
    EXPECT_CONTAINS_ALL(textureWarning,
                        dir.path("mats/a.mtl") + ":3: material 'tex': map_Kd texture 'missing.png' not found",
                        "looked for " + dir.path("mats/missing.png"), "magenta and black checker");
    expectChecker(scene);
}

TEST(ObjTexture, TextureThatIsNotAnImageWarnsAndShowsTheChecker) {
    test::TempDir dir;
    dir.write("mats/a.mtl", "newmtl tex\n\nmap_Kd notes.png\n");
    dir.write("mats/notes.png", "this is text, not a PNG\n");
    std::string obj = dir.write("model.obj", kQuad + "f 1/1 2/2 3/3\n");
    {
        WarningCapture capture;
        Scene scene = loadObj(obj);
        EXPECT_CONTAINS_ALL(
            onlyWarning(capture),
            dir.path("mats/a.mtl") + ":3: material 'tex': map_Kd " + dir.path("mats/notes.png"),
            "not an image", "checker");
        expectChecker(scene);
    }
    // An HDR image is radiance, not a colour.
    dir.write("mats/notes.png", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x80\x80\x81");
    {
        WarningCapture capture;
        Scene scene = loadObj(obj);
        EXPECT_CONTAINS_ALL(onlyWarning(capture), dir.path("mats/a.mtl") + ":3: material 'tex': map_Kd ",
                            "Radiance HDR");
        expectChecker(scene);
    }
    // A directory is no texture either.
    dir.write("mats/dir.png/x", "");
    dir.write("mats/a.mtl", "newmtl tex\nmap_Kd dir.png\n");
    {
        WarningCapture capture;
        Scene scene = loadObj(obj);
        EXPECT_CONTAINS_ALL(onlyWarning(capture), ":2: material 'tex': map_Kd texture 'dir.png' not found");
        expectChecker(scene);
    }
}

TEST(ObjTexture, StrictModeMakesABrokenTextureAnError) {
    test::TempDir dir;
    dir.write("mats/a.mtl", "newmtl tex\nmap_Kd missing.png\n");
    std::string obj = dir.write("model.obj", kQuad + "f 1/1 2/2 3/3\n");
    setStrictWarnings(true);
    std::string message = test::errorOf([&] { loadObj(obj); });
    setStrictWarnings(false);
    EXPECT_CONTAINS_ALL(message, ":2: material 'tex': map_Kd texture 'missing.png' not found", "--strict");
}

TEST(ObjTexture, TheCheckerIsMagentaAndBlackSquaresOfEightTexels) {
    Rgba8Image checker = missingTextureChecker();
    ASSERT_EQ(checker.width, 64);
    ASSERT_EQ(checker.height, 64);
    auto texel = [&](int x, int y) {
        const uint8_t* t = &checker.texels[(size_t(y) * 64 + size_t(x)) * 4];
        return std::array<int, 4>{t[0], t[1], t[2], t[3]};
    };
    const std::array<int, 4> magenta{255, 0, 255, 255}, black{0, 0, 0, 255};
    EXPECT_EQ(texel(0, 0), magenta);
    EXPECT_EQ(texel(7, 7), magenta);
    EXPECT_EQ(texel(8, 0), black);
    EXPECT_EQ(texel(0, 8), black);
    EXPECT_EQ(texel(8, 8), magenta);
    EXPECT_EQ(texel(63, 0), black);
    EXPECT_EQ(texel(63, 63), magenta);
}

TEST(ObjTexture, TexturesOfUnusedMaterialsAreNotLoaded) {
    WarningCapture capture;
    Scene scene = loadTextured("f 1/1 2/2 3/3\n",
                               "newmtl unused\nmap_Kd missing.png\nnewmtl tex\nmap_Kd tex.png\nnewmtl also\n"
                               "Kd 0.5\nmap_Kd tex.png\n");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.textures.size(), 1u);
    for (const Material& m : scene.materials)
        if (m.name != "tex") {
            EXPECT_EQ(m.diffuseTexture, -1) << m.name;
        }
}

TEST(ObjTexture, OneFileUsedByTwoMaterialsIsLoadedOnce) {
    Scene scene = loadTextured("f 1/1 2/2 3/3\nusemtl other\nf 1/1 3/3 4/4\n",
                               "newmtl tex\nmap_Kd tex.png\nnewmtl other\nKd 0.5\nmap_Kd ./tex.png\n");
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_NE(scene.triangles[0].material, scene.triangles[1].material);
    EXPECT_EQ(scene.textures.size(), 1u);
}

TEST(ObjTexture, NonFiniteTexcoordsAreRepairedAsNone) {
    WarningCapture capture;
    Scene scene = loadTextured("vt nan 0\nf 1/1 2/2 3/-1\n");
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_TRUE(capture.contains("used no texture coordinates on 1 face with NaN or infinite ones"))
        << test::joined(capture);
    EXPECT_EQ(scene.materials[scene.triangles[0].material].diffuseTexture, -1);
}

TEST(ObjTexture, SceneFilesLoadTexturesThroughTheirMesh) {
    test::TempDir dir;
    dir.write("mesh/mats/a.mtl", "newmtl tex\nmap_Kd tex.png\n");
    dir.write("mesh/mats/tex.png", test::pngBytes(2, 2, kTexels));
    dir.write("mesh/model.obj", kQuad + "f 1/1 2/2 3/3\n");
    Scene scene = loadScene(dir.write("scene.json", R"({"mesh": "mesh/model.obj"})"));
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].image.texels, kTexels);
}

}  // namespace
}  // namespace fp
