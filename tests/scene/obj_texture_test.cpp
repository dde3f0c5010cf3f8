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

// The other maps, as their kind makes them (mtl.h): map_d's coverage goes to A (the file's alpha, else
// its luminance, or the channel -imfchan names), map_Pr and map_Pm are combined into G and B (255 where
// one is missing; at the larger size, nearest texels, with a warning), a normal map is kept as it is.
TEST(ObjTexture, MapsAreLoadedAsTheirKind) {
    test::TempDir dir;
    dir.write("mats/grey.png", test::pngBytes(2, 1, 1, {10, 200}));
    dir.write("mats/rgba.png", test::pngBytes(1, 1, 4, {100, 150, 200, 77}));
    dir.write("mats/rgb.png", test::pngBytes(2, 1, 3, {255, 0, 0, 0, 255, 0}));
    dir.write("mats/rough.png", test::pngBytes(2, 2, 1, {1, 2, 3, 4}));
    dir.write("mats/normal.png", test::pngBytes(1, 1, 3, {128, 128, 255}));
    dir.write("mats/a.mtl",
              "newmtl tex\nKd 1\nmap_d grey.png\n"
              "newmtl b\nKd 1\nmap_d rgba.png\n"
              "newmtl c\nKd 1\nmap_d rgb.png\n"
              "newmtl d\nKd 1\nmap_d -imfchan b rgba.png\n"
              "newmtl e\nKd 1\nPm 1\nmap_Pr rough.png\nmap_Pm -imfchan g rgb.png\n"
              "newmtl f\nKd 1\nmap_Pr rough.png\nKs 1\nmap_Bump normal.png\n");
    std::string faces;
    for (const char* m : {"tex", "b", "c", "d", "e", "f"})
        faces += std::string("usemtl ") + m + "\nf 1/1 2/2 3/3\n";
    WarningCapture capture;
    Scene scene = loadObj(dir.write("model.obj", kQuad + faces));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0],
                        "a.mtl:17: map_Pm 'rgb.png' and map_Pr 'rough.png' differ in size");
    auto texels = [&](const std::string& name) -> std::vector<uint8_t> {
        for (const Material& m : scene.materials)
            if (m.name == name) {
                int32_t t = m.alphaTexture >= 0 ? m.alphaTexture : m.metallicRoughnessTexture;
                return scene.textures[size_t(t)].image.texels;
            }
        return {};
    };
    EXPECT_EQ(texels("tex"), (std::vector<uint8_t>{10, 10, 10, 10, 200, 200, 200, 200}))
        << "grey: A = the grey";
    EXPECT_EQ(texels("b"), (std::vector<uint8_t>{100, 150, 200, 77})) << "the file's alpha";
    // No alpha: the luminance, 0.2126 * 255 = 54.2 and 0.7152 * 255 = 182.4, rounded.
    EXPECT_EQ(texels("c"), (std::vector<uint8_t>{255, 0, 0, 54, 0, 255, 0, 182}));
    EXPECT_EQ(texels("d"), (std::vector<uint8_t>{100, 150, 200, 200})) << "-imfchan b";
    // 2x2 from the 2x2 roughness (G) and the 2x1 metallic's green channel (B), nearest texel.
    EXPECT_EQ(texels("e"),
              (std::vector<uint8_t>{0, 1, 0, 255, 0, 2, 255, 255, 0, 3, 0, 255, 0, 4, 255, 255}));
    for (const Material& m : scene.materials)
        if (m.name == "f") {
            // A plastic's roughness map without map_Pm: B = 255; the RGB normal map as it is.
            EXPECT_EQ(scene.textures[size_t(m.metallicRoughnessTexture)].image.texels,
                      (std::vector<uint8_t>{0, 1, 255, 255, 0, 2, 255, 255, 0, 3, 255, 255, 0, 4, 255, 255}));
            ASSERT_GE(m.normalTexture, 0);
            EXPECT_EQ(scene.textures[size_t(m.normalTexture)].image.texels,
                      (std::vector<uint8_t>{128, 128, 255, 255}));
        }
}

// The MTL spec's bump is a height map, which we do not support: a greyscale file named by map_Bump or
// bump is refused with one warning naming it, and the material keeps its shading normals. The same
// file as a colour map is loaded as usual.
TEST(ObjTexture, GreyscaleBumpMapsAreHeightMapsAndIgnored) {
    test::TempDir dir;
    dir.write("mats/height.png", test::pngBytes(2, 1, 1, {10, 200}));
    dir.write("mats/a.mtl",
              "newmtl tex\nmap_Kd height.png\nbump -bm 0.3 height.png\nnewmtl b\nmap_Bump height.png\n");
    WarningCapture capture;
    Scene scene = loadObj(dir.write("model.obj", kQuad + "f 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 4/4\n"));
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "a.mtl:3: map_Bump 'height.png' is a greyscale image",
                        "height maps are not supported");
    for (const Material& m : scene.materials) EXPECT_EQ(m.normalTexture, -1) << m.name;
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials[scene.triangles[0].material].diffuseTexture, 0);
}

// A missing map other than map_Kd is named by its statement and material: a colour map (map_Ke) shows
// the checker, any other (map_Pm) is ignored and the factor alone counts.
TEST(ObjTexture, MissingMapNamesItsStatementAndMaterial) {
    test::TempDir dir;
    dir.write("mats/a.mtl", "newmtl tex\nKd 1\nPm 1\nmap_Pm metal.png\nKe 1\nmap_Ke glow.png\n");
    std::string obj = dir.write("model.obj", kQuad + "f 1/1 2/2 3/3\n");
    WarningCapture capture;
    Scene scene = loadObj(obj);
    std::string warnings = test::joined(capture);
    EXPECT_CONTAINS_ALL(warnings,
                        dir.path("mats/a.mtl") + ":4: material 'tex': map_Pm texture 'metal.png' not found",
                        "; ignoring the map",
                        dir.path("mats/a.mtl") + ":6: material 'tex': map_Ke texture 'glow.png' not found",
                        "; showing a magenta and black checker instead");
    const Material& m = scene.materials[scene.triangles[0].material];
    EXPECT_EQ(m.metallicRoughnessTexture, -1);
    EXPECT_EQ(m.metallic, 1.0f);
    ASSERT_GE(m.emissionTexture, 0);
    EXPECT_EQ(scene.textures[size_t(m.emissionTexture)].image.texels, missingTextureChecker().texels);
}

// Faces without vt on a material with maps: every map gives way to its mean (Ke times the emission
// map's mean colour, roughness and metallic times the means of G and B, alpha times the mean of A) and
// the normal map is dropped.
TEST(ObjTexture, FacesWithoutTexcoordsGetEveryMapsMean) {
    test::TempDir dir;
    dir.write("mats/orm.png", test::pngBytes(2, 1, 4, {0, 51, 102, 255, 0, 153, 204, 0}));
    dir.write("mats/n.png", test::pngBytes(1, 1, 3, {200, 128, 230}));
    dir.write("mats/a.mtl",
              "newmtl tex\nKd 1\nPm 0.5\nPr 0.5\nKe 2\nmap_Pr -imfchan g orm.png\nmap_Pm -imfchan b orm.png\n"
              "map_d orm.png\nmap_Ke orm.png\nnorm n.png\n");
    WarningCapture capture;
    Scene scene = loadObj(dir.write("model.obj", kQuad + "f 1 2 3\n"));
    ASSERT_EQ(scene.triangles.size(), 1u);
    const Material& m = scene.materials[scene.triangles[0].material];
    EXPECT_FALSE(m.hasTextures());
    EXPECT_NEAR(m.roughness, 0.5f * (51 + 153) / 510.0f, 1e-6f);
    EXPECT_NEAR(m.metallic, 0.5f * (102 + 204) / 510.0f, 1e-6f);
    EXPECT_NEAR(m.alpha, 0.5f, 1e-6f);
    EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
    EXPECT_NEAR(m.emission.g, 2.0f * 0.5f * (srgbDecode(0.2f) + srgbDecode(0.6f)), 1e-5f);
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
