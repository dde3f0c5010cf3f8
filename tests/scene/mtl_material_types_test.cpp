// MTL statements -> Diffuse, Conductor, Plastic, Dielectric, MetallicRoughness: every rule of mtl.h with a
// snippet, the texture maps and their options, coverage, the sanitising of the statements the rules
// read, and the warnings about statements we do not read.
#include <gtest/gtest.h>

#include "scene/builtin_scene.h"
#include "scene/mtl.h"
#include "scene_test_util.h"

namespace fp {
namespace {

#define EXPECT_VEC3_NEAR(actual, expected)                                                           \
    do {                                                                                             \
        const glm::vec3 fp_a_ = (actual), fp_e_ = (expected);                                        \
        for (int fp_c_ = 0; fp_c_ < 3; ++fp_c_)                                                      \
            EXPECT_NEAR(fp_a_[fp_c_], fp_e_[fp_c_], 1e-6f) << "channel " << fp_c_ << " of " #actual; \
    } while (0)

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

// The materials of `mtl` and the warnings parsing it gave.
struct Parsed {
    std::vector<Material> materials;
    std::vector<std::string> warnings;
    std::vector<MtlTexture> textures;
};
Parsed parse(const std::string& mtl) {
    WarningCapture capture;
    Parsed out;
    out.materials = parseMtl(mtl, "t.mtl", &out.textures);
    out.warnings = capture.messages();
    return out;
}

// The one material of "newmtl m\n" + `body`, which must parse without warnings.
Material quiet(const std::string& body) {
    Parsed p = parse("newmtl m\n" + body);
    EXPECT_TRUE(p.warnings.empty()) << "for:\n" << body << "warnings:\n" << joined(p.warnings);
    EXPECT_EQ(p.materials.size(), 1u) << body;
    return p.materials.empty() ? Material{} : p.materials[0];
}

// The one material of "newmtl m\n" + `body`, which must give exactly the warning containing `warning`.
Material warned(const std::string& body, const std::string& warning) {
    Parsed p = parse("newmtl m\n" + body);
    EXPECT_EQ(p.warnings.size(), 1u) << body << joined(p.warnings);
    if (!p.warnings.empty()) EXPECT_CONTAINS_ALL(p.warnings[0], "t.mtl: ", warning);
    EXPECT_EQ(p.materials.size(), 1u) << body;
    return p.materials.empty() ? Material{} : p.materials[0];
}

// ---- the Cornell box ----

TEST(MtlTypes, CornellBoxStaysDiffuse) {
    WarningCapture capture;
    Scene scene = builtinCornellBox();
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.materials.size(), 4u);
    for (const Material& m : scene.materials) {
        EXPECT_EQ(m.type, MaterialType::Diffuse) << m.name;
        EXPECT_EQ(m.specular, glm::vec3(0.0f)) << m.name;
    }
    EXPECT_EQ(scene.materials[3].name, "light");
    EXPECT_EQ(scene.materials[3].emission, glm::vec3(17.0f, 12.0f, 4.0f));
}

// ---- rule 1: Dielectric ----

TEST(MtlTypes, TransparentIllumModelsAreGlass) {
    for (int illum : {4, 6, 7, 9}) {
        Material m = quiet("Kd 0.2 0.2 0.2\nillum " + std::to_string(illum) + "\n");
        EXPECT_EQ(m.type, MaterialType::Dielectric) << illum;
        EXPECT_EQ(m.ior, 1.5f) << "Ni absent gives 1.5, not the MTL default 1";
        EXPECT_EQ(m.transmission, glm::vec3(1.0f)) << "no Tf gives white";
        EXPECT_EQ(m.roughness, 0.0f) << "no Pr gives smooth glass";
    }
}

TEST(MtlTypes, GlassReadsNiTfAndPr) {
    Material m = quiet("illum 7\nNi 1.33\nTf 0.9 0.95 1\nPr 0.2\n");
    EXPECT_EQ(m.type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_VEC3_NEAR(m.transmission, glm::vec3(0.9f, 0.95f, 1.0f));
    EXPECT_FLOAT_EQ(m.roughness, 0.2f);
    // An explicit Ni is kept, even the MTL default 1 (the glass then shows only its tint).
    EXPECT_EQ(quiet("illum 4\nNi 1\n").ior, 1.0f);
    // A black Tf is "not given": the glass is white.
    EXPECT_EQ(quiet("illum 4\nTf 0 0 0\n").transmission, glm::vec3(1.0f));
}

TEST(MtlTypes, TintWithoutIllumIsGlass) {
    Material tf = quiet("Kd 0.5 0.5 0.5\nTf 0.5 0.8 1\n");
    EXPECT_EQ(tf.type, MaterialType::Dielectric);
    EXPECT_VEC3_NEAR(tf.transmission, glm::vec3(0.5f, 0.8f, 1.0f));
    EXPECT_EQ(tf.ior, 1.5f);
    // tinyobjloader reads Kt into the same field as Tf; so do we.
    Material kt = quiet("Kt 0.25\n");
    EXPECT_EQ(kt.type, MaterialType::Dielectric);
    EXPECT_EQ(kt.transmission, glm::vec3(0.25f));
    EXPECT_EQ(quiet("Tf 0 0 0\n").type, MaterialType::Diffuse);
}

TEST(MtlTypes, ExplicitOpaqueIllumWinsOverTf) {
    // The block 3ds Max's exporter writes for every opaque material (the Dabrovic Sponza is full of
    // them): Tf 1 1 1 is the filter of a material that lets nothing through; it must stay Diffuse.
    Material sponza = quiet(
        "\tNs 50.000000\n\tNi 1.500000\n\td 1.000000\n\tTr 0.000000\n\tTf 1.000000 1.000000 1.000000 \n"
        "\tillum 2\n\tKa 0.000000 0.000000 0.000000\n\tKd 0.745098 0.709804 0.674510\n"
        "\tKs 0.000000 0.000000 0.000000\n\tKe 0.000000 0.000000 0.000000\n\tmap_Ka sp_luk.jpg\n"
        "\tmap_bump sp_luk-bump.JPG\n\tbump sp_luk-bump.JPG\n");
    EXPECT_EQ(sponza.type, MaterialType::Diffuse);
    EXPECT_VEC3_NEAR(sponza.diffuse, glm::vec3(0.745098f, 0.709804f, 0.674510f));
    for (int illum : {0, 1, 2, 3, 5, 8, 10})
        EXPECT_NE(quiet("Tf 1 1 1\nillum " + std::to_string(illum) + "\n").type, MaterialType::Dielectric)
            << illum;
    // With a highlight the same block is plastic, not glass.
    EXPECT_EQ(quiet("Tf 1 1 1\nillum 2\nKs 0.2 0.2 0.2\n").type, MaterialType::Plastic);
}

TEST(MtlTypes, DissolveNeverSelectsGlass) {
    // d and Tr are opacity (cut-outs), not transmission; accepted without a word, even both at once.
    EXPECT_EQ(quiet("Kd 0.5 0.5 0.5\nd 0.2\n").type, MaterialType::Diffuse);
    EXPECT_EQ(quiet("Kd 0.5 0.5 0.5\nTr 0.8\n").type, MaterialType::Diffuse);
    EXPECT_EQ(quiet("Kd 0.5 0.5 0.5\nd 0.5\nTr 0.5\n").type, MaterialType::Diffuse);
}

// d is coverage (alpha), for every type: below 1 (or with map_d) the material is BLEND, otherwise it
// stays opaque. Tr is ignored (exporters disagree on its meaning), before or after d.
TEST(MtlTypes, DissolveIsCoverage) {
    Material m = quiet("Kd 0.5\nd 0.25\n");
    EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
    EXPECT_EQ(m.alpha, 0.25f);
    Material opaque = quiet("Kd 0.5\nd 1\n");
    EXPECT_EQ(opaque.alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(opaque.alpha, 1.0f);
    for (std::string body : {"Kd 0.5\nTr 1\n", "Kd 0.5\nTr 0.3\n", "Kd 0.5\nTr 0\n"}) {
        Material tr = quiet(body);
        EXPECT_EQ(tr.alphaMode, AlphaMode::Opaque) << body;
        EXPECT_EQ(tr.alpha, 1.0f) << body;
    }
    EXPECT_EQ(quiet("Kd 0.5\nTr 0.9\nd 0.5\n").alpha, 0.5f);
    EXPECT_EQ(quiet("Kd 0.5\nd 0.5\nTr 0.9\n").alpha, 0.5f);
    // Coverage for glass and metals too.
    EXPECT_EQ(quiet("illum 4\nd 0.5\n").alphaMode, AlphaMode::Blend);
    EXPECT_EQ(quiet("Kd 1\nPm 1\nd 0.5\n").alphaMode, AlphaMode::Blend);
    // A map of it makes the material BLEND whatever d says (it multiplies d).
    Parsed mapped = parse("newmtl m\nKd 0.5\nmap_d mask.png\n");
    ASSERT_EQ(mapped.materials.size(), 1u);
    EXPECT_EQ(mapped.materials[0].alphaMode, AlphaMode::Blend);
    EXPECT_EQ(mapped.materials[0].alpha, 1.0f);
    EXPECT_EQ(mapped.materials[0].alphaTexture, 0);
    ASSERT_EQ(mapped.textures.size(), 1u);
    EXPECT_EQ(mapped.textures[0].kind, MtlTextureKind::Alpha);
    EXPECT_EQ(mapped.textures[0].file, "mask.png");
    // Clamped and checked as the other scalars.
    EXPECT_EQ(warned("Kd 0.5\nd 1.5\n", "clamped 1 d value to [0, 1]").alpha, 1.0f);
    EXPECT_EQ(warned("Kd 0.5\nd nan\n", "ignored 1 d statement with a NaN").alphaMode, AlphaMode::Opaque);
}

TEST(MtlTypes, GlassWinsOverMetalAndSpecular) {
    EXPECT_EQ(quiet("illum 4\nPm 1\nKs 1 1 1\n").type, MaterialType::Dielectric);
    EXPECT_EQ(quiet("Tf 0.9 0.9 0.9\nPm 1\n").type, MaterialType::Dielectric);
}

// ---- rule 2: MetallicRoughness from Pm or map_Pm ----

TEST(MtlTypes, MetallicIsMetallicRoughnessWithKdAsBaseColour) {
    Material gold = quiet("Kd 1 0.78 0.34\nKs 0.1 0.1 0.1\nPm 1\nPr 0.3\n");
    EXPECT_EQ(gold.type, MaterialType::MetallicRoughness);
    EXPECT_VEC3_NEAR(gold.diffuse, glm::vec3(1.0f, 0.78f, 0.34f));  // Kd, not Ks
    EXPECT_EQ(gold.metallic, 1.0f);
    EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
    EXPECT_EQ(gold.ior, 1.5f);
    EXPECT_EQ(quiet("Kd 0.9 0.9 0.9\nPm 1\n").roughness, 0.5f) << "no Pr gives 0.5";
    // Any Pm: the blend, or the dielectric end of the model (Ks is not part of it).
    for (float pm : {0.0f, 0.3f, 0.5f, 0.75f}) {
        Material m = quiet("Kd 0.9 0.9 0.9\nKs 0.5 0.5 0.5\nNi 1.45\nPm " + std::to_string(pm) + "\n");
        EXPECT_EQ(m.type, MaterialType::MetallicRoughness) << pm;
        EXPECT_FLOAT_EQ(m.metallic, pm);
        EXPECT_FLOAT_EQ(m.ior, 1.45f) << "the coat's index, as a plastic's";
    }
    EXPECT_EQ(quiet("Kd 0.9\nPm 0\nNi 1\n").ior, 1.5f) << "Ni 1 means nothing on an opaque material";
    // map_Pm alone selects the model too, its factor 1; map_Pr alone makes the roughness factor 1.
    Parsed mapped = parse("newmtl m\nKd 0.9\nmap_Pm metal.png\nmap_Pr rough.png\n");
    ASSERT_EQ(mapped.materials.size(), 1u);
    EXPECT_TRUE(mapped.warnings.empty()) << joined(mapped.warnings);
    EXPECT_EQ(mapped.materials[0].type, MaterialType::MetallicRoughness);
    EXPECT_EQ(mapped.materials[0].metallic, 1.0f);
    EXPECT_EQ(mapped.materials[0].roughness, 1.0f);
}

// ---- rule 3: Conductor from illum 5 ----

TEST(MtlTypes, FresnelMirrorIsConductorWithKs) {
    Material mirror = quiet("Kd 0.1 0.1 0.1\nKs 0.95 0.9 0.8\nNs 200\nillum 5\n");
    EXPECT_EQ(mirror.type, MaterialType::Conductor);
    EXPECT_VEC3_NEAR(mirror.specular, glm::vec3(0.95f, 0.9f, 0.8f));
    EXPECT_EQ(mirror.roughness, 0.0f) << "a mirror, whatever Ns says";
    EXPECT_FLOAT_EQ(quiet("Ks 1 1 1\nPr 0.1\nillum 5\n").roughness, 0.1f);
    // A Pm statement means the PBR convention, which wins over illum 5.
    EXPECT_EQ(quiet("Ks 1 1 1\nPm 0\nillum 5\n").type, MaterialType::MetallicRoughness);
    EXPECT_EQ(quiet("Kd 0.5 0.5 0.5\nillum 5\n").type, MaterialType::Diffuse);
}

// ---- rule 4: Plastic ----

TEST(MtlTypes, SpecularIsPlastic) {
    Material m = quiet("Kd 0.5 0.1 0.1\nKs 0.04 0.04 0.04\nNs 10\nillum 2\n");
    EXPECT_EQ(m.type, MaterialType::Plastic);
    EXPECT_VEC3_NEAR(m.diffuse, glm::vec3(0.5f, 0.1f, 0.1f));
    EXPECT_VEC3_NEAR(m.specular, glm::vec3(0.04f));
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_NEAR(m.roughness, 0.6389431f, 1e-6f);  // (2 / 12)^(1/4)
    EXPECT_FLOAT_EQ(quiet("Ks 1 1 1\nNi 1.4\n").ior, 1.4f);
    EXPECT_FLOAT_EQ(quiet("Ks 1 1 1\nNs 10\nPr 0.25\n").roughness, 0.25f) << "Pr wins over Ns";
    EXPECT_EQ(quiet("Ks 1 1 1\n").roughness, 0.5f) << "neither Pr nor Ns";
    // Ray-traced reflection (3), a plain highlight (2), or no illum at all: all plastic.
    for (std::string illum : {"illum 2\n", "illum 3\n", "illum 8\n", ""})
        EXPECT_EQ(quiet("Ks 0.5 0.5 0.5\n" + illum).type, MaterialType::Plastic) << illum;
}

TEST(MtlTypes, BlenderExportIsPlastic) {
    // What Blender's OBJ exporter writes for its default material.
    Material m = quiet(
        "Ns 250.000000\nKa 1.000000 1.000000 1.000000\nKd 0.800000 0.800000 0.800000\n"
        "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 2\n");
    EXPECT_EQ(m.type, MaterialType::Plastic);
    EXPECT_FLOAT_EQ(m.ior, 1.45f);
    EXPECT_NEAR(m.roughness, 0.2984746f, 1e-6f);  // (2 / 252)^(1/4)
}

TEST(MtlTypes, IllumZeroAndOneSwitchSpecularOff) {
    // The spec's models 0 and 1 have no Ks term.
    EXPECT_EQ(quiet("Ks 1 1 1\nillum 0\n").type, MaterialType::Diffuse);
    EXPECT_EQ(quiet("Ks 1 1 1\nillum 1\n").type, MaterialType::Diffuse);
    EXPECT_EQ(quiet("Ks 1 1 1\nillum 1\nPm 1\n").type, MaterialType::MetallicRoughness) << "Pm ignores illum";
}

// ---- rule 5 and emission ----

TEST(MtlTypes, EverythingElseIsDiffuse) {
    Material m = quiet("Kd 0.3 0.4 0.5\nKs 0 0 0\nNs 90\nNi 1.2\nillum 2\n");
    EXPECT_EQ(m.type, MaterialType::Diffuse);
    EXPECT_VEC3_NEAR(m.diffuse, glm::vec3(0.3f, 0.4f, 0.5f));
    // Fields a Diffuse material does not use keep their defaults.
    EXPECT_EQ(m.specular, glm::vec3(0.0f));
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.roughness, 0.0f);
}

TEST(MtlTypes, EmissionKeptForEveryType) {
    const std::pair<std::string, MaterialType> cases[] = {
        {"Kd 0.5 0.5 0.5\n", MaterialType::Diffuse},
        {"Kd 0.5 0.5 0.5\nPm 1\n", MaterialType::MetallicRoughness},
        {"Ks 0.5 0.5 0.5\nillum 5\n", MaterialType::Conductor},
        {"Ks 0.5 0.5 0.5\n", MaterialType::Plastic},
        {"illum 4\n", MaterialType::Dielectric},
    };
    for (const auto& [body, type] : cases) {
        Material m = quiet(body + "Ke 1 2 3\n");
        EXPECT_EQ(m.type, type) << body;
        EXPECT_EQ(m.emission, glm::vec3(1.0f, 2.0f, 3.0f)) << body;
    }
}

// ---- the Phong exponent ----

TEST(MtlTypes, PhongExponentToRoughness) {
    // (2 / (Ns + 2))^(1/4), worked out by hand.
    EXPECT_FLOAT_EQ(roughnessFromPhong(0.0f), 1.0f);
    EXPECT_NEAR(roughnessFromPhong(2.0f), 0.8408964f, 1e-6f);     // 0.5^(1/4)
    EXPECT_NEAR(roughnessFromPhong(10.0f), 0.6389431f, 1e-6f);    // (1/6)^(1/4)
    EXPECT_NEAR(roughnessFromPhong(98.0f), 0.3760603f, 1e-6f);    // 0.02^(1/4)
    EXPECT_NEAR(roughnessFromPhong(1000.0f), 0.2113686f, 1e-6f);  // (2/1002)^(1/4)
    float previous = 2.0f;
    for (float ns = 0.0f; ns <= 10000.0f; ns = ns * 2.0f + 1.0f) {
        float r = roughnessFromPhong(ns);
        EXPECT_LT(r, previous) << ns;
        EXPECT_GT(r, 0.0f) << ns;
        previous = r;
    }
    EXPECT_NEAR(quiet("Ks 1 1 1\nNs 98\n").roughness, 0.3760603f, 1e-6f);
}

// ---- sanitising ----

TEST(MtlTypes, SpecularAndTintClamped) {
    Material ks = warned("Ks 1.5 -0.5 0.5\n", "clamped 2 Ks values to [0, 1] (first at line 2)");
    EXPECT_EQ(ks.specular, glm::vec3(1.0f, 0.0f, 0.5f));
    Material tf = warned("Kd 0.5\nTf 2 0.5 -1\n", "clamped 2 Tf values to [0, 1] (first at line 3)");
    EXPECT_EQ(tf.transmission, glm::vec3(1.0f, 0.5f, 0.0f));
    Material nan = warned("Ks nan 0.5 inf\n", "replaced 2 NaN or infinite Ks values by 0 (first at line 2)");
    EXPECT_EQ(nan.specular, glm::vec3(0.0f, 0.5f, 0.0f));
    // One warning per kind of repair, naming every statement that needed it.
    Parsed both = parse("newmtl a\nKd 2 0 0\nKs 0 3 0\nnewmtl b\nTf -1 0 0\nKs 4 0 0\n");
    ASSERT_EQ(both.warnings.size(), 1u);
    EXPECT_CONTAINS_ALL(both.warnings[0], "clamped 4 Kd/Ks/Tf values to [0, 1] (first at line 2)");
}

TEST(MtlTypes, RoughnessAndMetallicClamped) {
    Material pr = warned("Ks 1 1 1\nPr 1.5\n", "clamped 1 Pr value to [0, 1] (first at line 3)");
    EXPECT_EQ(pr.roughness, 1.0f);
    Material pm = warned("Kd 0.5\nPm 7\nPr -1\n", "clamped 2 Pm/Pr values to [0, 1] (first at line 3)");
    EXPECT_EQ(pm.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(pm.metallic, 1.0f);
    EXPECT_EQ(pm.roughness, 0.0f);
}

TEST(MtlTypes, IorClampedToOneToFour) {
    Material low = warned("illum 4\nNi 0.5\n", "clamped 1 Ni value to [1, 4] (first at line 3)");
    EXPECT_EQ(low.ior, 1.0f);
    Material high = warned("illum 4\nNi 7\n", "clamped 1 Ni value to [1, 4] (first at line 3)");
    EXPECT_EQ(high.ior, 4.0f);
    EXPECT_FLOAT_EQ(quiet("illum 4\nNi 2.42\n").ior, 2.42f) << "diamond is in range";
}

TEST(MtlTypes, NonFiniteScalarsGiveDefaults) {
    Material ni =
        warned("illum 4\nNi nan\n", "ignored 1 Ni statement with a NaN or infinite value (first at line 3)");
    EXPECT_EQ(ni.ior, 1.5f);
    Material ns = warned("Ks 1 1 1\nNs inf\n", "ignored 1 Ns statement with a NaN or infinite value");
    EXPECT_EQ(ns.roughness, 0.5f);
    Material pm =
        warned("Kd 0.5\nPm NaN\nPr 1e39\n", "ignored 2 Pm/Pr statements with a NaN or infinite value");
    EXPECT_EQ(pm.type, MaterialType::Diffuse);
}

TEST(MtlTypes, NegativeExponentSetToZero) {
    Material m = warned("Ks 1 1 1\nNs -5\n", "set 1 negative Ns value to 0 (first at line 3)");
    EXPECT_EQ(m.roughness, 1.0f);
}

TEST(MtlTypes, MalformedScalarStatementsIgnored) {
    // illum -1 and 2.5 are no illumination models (tinyobjloader would read 2.5 as 2).
    Material m = warned("Ks 1 1 1\nNi\nNs 1 2\nPr abc\nillum 2.5\nillum -1\n",
                        "ignored 5 malformed Ni/Ns/Pr/illum statements (first at line 3)");
    EXPECT_EQ(m.type, MaterialType::Plastic);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.roughness, 0.5f);
}

TEST(MtlTypes, SanitizeRespellsScalarsKeepingLines) {
    WarningCapture capture;
    std::vector<MtlGiven> given;
    std::string clean = sanitizeMtl(
        "Ni 2\nnewmtl x\nNi 7\nNs -1\nPr 2 # rough\nPm 0.25\nillum  4\nKs 2 0.5 nan\nTf 0.5\nNi nan\n",
        "t.mtl", &given);
    EXPECT_EQ(clean, "Ni 2\nnewmtl x\nNi 4\nNs 0\nPr 1\nPm 0.25\nillum 4\nKs 1 0.5 0\nTf 0.5 0.5 0.5\n\n");
    ASSERT_EQ(given.size(), 1u) << "the Ni before any newmtl belongs to no material";
    EXPECT_TRUE(given[0].ni && given[0].ns && given[0].pr && given[0].pm && given[0].illum);
}

TEST(MtlTypes, StatementsBelongToTheirMaterial) {
    // Which statements were given is tracked per material, the way tinyobjloader splits the file: a
    // newmtl without a name starts nothing (its statements go on filling the previous material).
    Parsed p = parse(
        "Ni 2\nillum 4\n"
        "newmtl a\nillum 4\nnewmtl\nNi 1.2\n"
        "newmtl b\nKs 1 1 1\n"
        "newmtl a\nNs 0\nKs 1 1 1\n");
    ASSERT_EQ(p.materials.size(), 3u);
    EXPECT_EQ(p.materials[0].type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(p.materials[0].ior, 1.2f);
    EXPECT_EQ(p.materials[1].type, MaterialType::Plastic);
    EXPECT_EQ(p.materials[1].ior, 1.5f);
    EXPECT_EQ(p.materials[1].roughness, 0.5f);
    EXPECT_EQ(p.materials[2].type, MaterialType::Plastic);
    EXPECT_EQ(p.materials[2].roughness, 1.0f);
}

// ---- statements we do not read ----

TEST(MtlTypes, UnknownStatementsWarnedOncePerName) {
    Parsed p = parse("newmtl a\nfoo 1\nKm 0.5\nfoo 2\nnewmtl b\nfoo 3\nKm 1\n");
    ASSERT_EQ(p.warnings.size(), 2u);
    EXPECT_EQ(p.warnings[0], "t.mtl: unknown MTL statement 'foo' ignored (first at line 2)");
    EXPECT_EQ(p.warnings[1], "t.mtl: unknown MTL statement 'Km' ignored (first at line 3)");
    // Once per file: the next library is told about it again.
    EXPECT_EQ(parse("newmtl c\nfoo 4\n").warnings.size(), 1u);
}

TEST(MtlTypes, HarmlessStatementsAcceptedSilently) {
    Material m = quiet(
        "Ka 1 1 1\nd 1\nTr 0\nsharpness 60\nPs 0\nPc 0\nPcr 0\naniso 0\nanisor 0\n"
        "disp d.png\ndecal c.png\nrefl -type sphere r.png\nmap_Ka a.png\nmap_Ns n.png\nmap_Disp d.png\n"
        "Kd 0.5\nKs 0\nKe 0\nTf 0\nNi 1.5\nNs 10\nillum 2\nPr 0.5\n");
    EXPECT_EQ(m.type, MaterialType::Diffuse);
    EXPECT_FALSE(m.hasTextures());
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
}

// ---- texture maps ----

// Every map statement we read, each on a type that uses it: its file and line for the loader, its kind,
// and the value it multiplies, 1 where the map comes alone (Ke with map_Ke, Ks with map_Ks).
TEST(MtlTypes, TextureMapsOfEveryKind) {
    Parsed p = parse(
        "newmtl plastic\nKd 0.5\nmap_Kd kd.png\nmap_Ks ks.png\nmap_Ke ke.png\nmap_Pr pr.png\n"
        "map_d d.png\nnorm n.png\n"
        "newmtl pbr\nKd 0.2\nPm 0.5\nKe 2 2 2\nmap_Ke ke.png\nmap_Pm pm.png\n");
    EXPECT_TRUE(p.warnings.empty()) << joined(p.warnings);
    ASSERT_EQ(p.materials.size(), 2u);
    const Material& a = p.materials[0];
    EXPECT_EQ(a.type, MaterialType::Plastic);
    EXPECT_EQ(a.specular, glm::vec3(1.0f)) << "map_Ks without Ks: Ks 1";
    EXPECT_EQ(a.emission, glm::vec3(1.0f)) << "map_Ke without Ke: Ke 1";
    EXPECT_EQ(a.roughness, 1.0f) << "map_Pr without Pr: roughness 1";
    EXPECT_EQ(a.alphaMode, AlphaMode::Blend);
    ASSERT_EQ(p.textures.size(), 8u);
    auto expectMap = [&p](int32_t index, const char* file, int line, MtlTextureKind kind,
                          const char* statement) {
        ASSERT_GE(index, 0) << file;
        const MtlTexture& t = p.textures[size_t(index)];
        EXPECT_EQ(t.file, file);
        EXPECT_EQ(t.line, line) << file;
        EXPECT_EQ(t.kind, kind) << file;
        EXPECT_EQ(t.statement, statement) << file;
    };
    expectMap(a.diffuseTexture, "kd.png", 3, MtlTextureKind::Color, "map_Kd");
    expectMap(a.specularTexture, "ks.png", 4, MtlTextureKind::Color, "map_Ks");
    expectMap(a.emissionTexture, "ke.png", 5, MtlTextureKind::Color, "map_Ke");
    expectMap(a.metallicRoughnessTexture, "pr.png", 6, MtlTextureKind::MetallicRoughness, "map_Pr");
    EXPECT_TRUE(p.textures[size_t(a.metallicRoughnessTexture)].metallicFile.empty());
    expectMap(a.alphaTexture, "d.png", 7, MtlTextureKind::Alpha, "map_d");
    expectMap(a.normalTexture, "n.png", 8, MtlTextureKind::Normal, "norm");
    const Material& b = p.materials[1];
    EXPECT_EQ(b.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(b.emission, glm::vec3(2.0f)) << "the map multiplies Ke";
    EXPECT_EQ(b.metallic, 0.5f) << "the map multiplies Pm";
    expectMap(b.emissionTexture, "ke.png", 13, MtlTextureKind::Color, "map_Ke");
    const MtlTexture& mr = p.textures[size_t(b.metallicRoughnessTexture)];
    EXPECT_EQ(mr.kind, MtlTextureKind::MetallicRoughness);
    EXPECT_TRUE(mr.file.empty()) << "no map_Pr";
    EXPECT_EQ(mr.metallicFile, "pm.png");
    EXPECT_EQ(mr.metallicLine, 14);
}

// norm, map_Bump, map_bump and bump name a tangent-space normal map; -bm scales it; norm wins.
TEST(MtlTypes, NormalMapStatementsAndTheirScale) {
    Parsed p = parse(
        "newmtl a\nnorm -bm 0.5 n.png\nnewmtl b\nmap_Bump -bm 2 b.png\nnewmtl c\nbump c.png\n"
        "newmtl d\nmap_bump d.png\nnewmtl e\nbump e.png\nnorm e_normal.png\nmap_Bump e2.png\n");
    EXPECT_TRUE(p.warnings.empty()) << joined(p.warnings);
    ASSERT_EQ(p.materials.size(), 5u);
    const char* files[] = {"n.png", "b.png", "c.png", "d.png", "e_normal.png"};
    const float scales[] = {0.5f, 2.0f, 1.0f, 1.0f, 1.0f};
    for (size_t i = 0; i < 5; ++i) {
        const Material& m = p.materials[i];
        ASSERT_GE(m.normalTexture, 0) << i;
        EXPECT_EQ(p.textures[size_t(m.normalTexture)].file, files[i]);
        EXPECT_EQ(p.textures[size_t(m.normalTexture)].kind, MtlTextureKind::Normal);
        EXPECT_EQ(m.normalScale, scales[i]) << i;
        EXPECT_EQ(m.type, MaterialType::Diffuse);
    }
    EXPECT_EQ(p.textures[size_t(p.materials[1].normalTexture)].statement, "map_Bump");
    EXPECT_EQ(p.textures[size_t(p.materials[2].normalTexture)].statement, "map_Bump") << "bump is map_Bump";
}

// map_Pr and map_Pm read one channel each (-imfchan r, g, b, m or l; luminance by default), so that one
// packed file serves both, as glTF's metallicRoughness texture does; the options we do not read are
// warned about once per file, naming every statement that had them.
TEST(MtlTypes, ScalarMapsReadTheChannelImfchanNames) {
    Parsed p = parse(
        "newmtl orm\nKd 1\nPm 1\nmap_Pr -imfchan g orm.png\nmap_Pm -imfchan b orm.png\n"
        "newmtl cut\nKd 1\nmap_d -imfchan r mask.png\n"
        "newmtl odd\nKd 1\nPm 1\nmap_Pr -imfchan z r.png\nmap_Kd -bm 2 k.png\n");
    ASSERT_EQ(p.materials.size(), 3u);
    const MtlTexture& orm = p.textures[size_t(p.materials[0].metallicRoughnessTexture)];
    EXPECT_EQ(orm.file, "orm.png");
    EXPECT_EQ(orm.channel, 'g');
    EXPECT_EQ(orm.metallicFile, "orm.png");
    EXPECT_EQ(orm.metallicChannel, 'b');
    EXPECT_EQ(p.textures[size_t(p.materials[1].alphaTexture)].channel, 'r');
    EXPECT_EQ(p.textures[size_t(p.materials[2].metallicRoughnessTexture)].channel, 0) << "z: not supported";
    ASSERT_EQ(p.warnings.size(), 1u) << joined(p.warnings);
    EXPECT_EQ(p.warnings[0],
              "t.mtl: ignored 2 map_Pr/map_Kd -imfchan/-bm options (textures repeat, unscaled and unshifted) "
              "(first at line 12)");
}

// A map on a type that does not use it is dropped, with one warning per statement and file.
TEST(MtlTypes, MapsOnTypesThatDoNotUseThemAreIgnoredWithAWarning) {
    Parsed p = parse(
        "newmtl pbr\nKd 1\nPm 1\nmap_Ks s.png\nnewmtl lambert\nKd 0.5\nmap_Pr r.png\n"
        "newmtl glass\nillum 4\nmap_Pm m.png\nmap_Pr r.png\nnewmtl off\nKd 0.5\nillum 1\nmap_Ks t.png\n");
    ASSERT_EQ(p.materials.size(), 4u);
    ASSERT_EQ(p.warnings.size(), 3u) << joined(p.warnings);
    EXPECT_EQ(p.warnings[0],
              "t.mtl: ignored map_Ks of 2 materials (only plastics and illum 5 metals have a Ks) (first at "
              "line 4)");
    EXPECT_EQ(p.warnings[1],
              "t.mtl: ignored map_Pr of 1 Lambertian material (no roughness) (first at line 7)");
    EXPECT_EQ(p.warnings[2],
              "t.mtl: ignored map_Pm of 1 glass material (glass is not metallic) (first at line 10)");
    EXPECT_EQ(p.materials[0].specularTexture, -1);
    EXPECT_EQ(p.materials[1].metallicRoughnessTexture, -1);
    EXPECT_EQ(p.materials[1].type, MaterialType::Diffuse);
    // The glass keeps its map_Pr (a rough glass's roughness), without the metallic part.
    EXPECT_EQ(p.materials[2].type, MaterialType::Dielectric);
    ASSERT_GE(p.materials[2].metallicRoughnessTexture, 0);
    EXPECT_EQ(p.textures[size_t(p.materials[2].metallicRoughnessTexture)].file, "r.png");
    EXPECT_TRUE(p.textures[size_t(p.materials[2].metallicRoughnessTexture)].metallicFile.empty());
    EXPECT_EQ(p.materials[3].specularTexture, -1);
}

TEST(MtlTypes, MapWithoutFileIsMalformed) {
    Material m = warned("Kd 0.3\nnorm -bm 2\nmap_d\n", "ignored 2 malformed norm/map_d statements");
    EXPECT_EQ(m.normalTexture, -1);
    EXPECT_EQ(m.alphaTexture, -1);
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
}

TEST(MtlTypes, DiffuseTextureNamesItsFileAndLineAndMultipliesKd) {
    Parsed p = parse(
        "newmtl a\nKd 0.2 0.3 0.4\nmap_Kd a.png\nnewmtl b\nmap_Kd my b.png # comment\n"
        "newmtl c\nKe 1\nnewmtl d\nKd 0.5\nmap_Kd tex\\wood.png\n");
    EXPECT_TRUE(p.warnings.empty()) << joined(p.warnings);
    ASSERT_EQ(p.materials.size(), 4u);
    ASSERT_EQ(p.textures.size(), 3u);
    EXPECT_EQ(p.materials[0].diffuseTexture, 0);
    EXPECT_EQ(p.textures[0].file, "a.png");
    EXPECT_EQ(p.textures[0].line, 3);
    EXPECT_VEC3_NEAR(p.materials[0].diffuse, glm::vec3(0.2f, 0.3f, 0.4f));
    // A texture without Kd is the colour alone (Kd 1), also after a material with Kd (where
    // tinyobjloader alone gives 0.6 or 0); names may contain blanks.
    EXPECT_EQ(p.materials[1].diffuseTexture, 1);
    EXPECT_EQ(p.textures[1].file, "my b.png");
    EXPECT_VEC3_NEAR(p.materials[1].diffuse, glm::vec3(1.0f));
    // Neither: Kd 0, no texture.
    EXPECT_EQ(p.materials[2].diffuseTexture, -1);
    EXPECT_EQ(p.materials[2].diffuse, glm::vec3(0.0f));
    // Windows separators become '/'.
    EXPECT_EQ(p.materials[3].diffuseTexture, 2);
    EXPECT_EQ(p.textures[2].file, "tex/wood.png");
}

TEST(MtlTypes, TextureOptionsAreWarnedAboutOncePerFile) {
    Parsed p = parse(
        "newmtl a\nmap_Kd -s 2 2 1 -clamp on a.png\nnewmtl b\nmap_Kd -o 0.5 -s 3 b.png\n"
        "newmtl c\nmap_Kd -mm 0 1 -blendu off -s 1 2 c d.png\n");
    ASSERT_EQ(p.warnings.size(), 1u) << joined(p.warnings);
    EXPECT_EQ(
        p.warnings[0],
        "t.mtl: ignored 7 map_Kd -s/-clamp/-o/-mm/-blendu options (textures repeat, unscaled and unshifted) "
        "(first at line 2)");
    ASSERT_EQ(p.textures.size(), 3u);
    EXPECT_EQ(p.textures[0].file, "a.png");
    EXPECT_EQ(p.textures[1].file, "b.png");
    EXPECT_EQ(p.textures[2].file, "c d.png");  // -s took 1 and 2; "c" is no number
}

TEST(MtlTypes, TextureWithoutFileIsMalformed) {
    Material m = warned("Kd 0.3\nmap_Kd\n", "ignored 1 malformed map_Kd statement");
    EXPECT_EQ(m.diffuseTexture, -1);
    EXPECT_VEC3_NEAR(m.diffuse, glm::vec3(0.3f));
}

TEST(MtlTypes, TextureOnMetalOrGlassIsIgnoredWithAWarning) {
    Parsed p = parse(
        "newmtl mirror\nKs 1 0.8 0.3\nillum 5\nmap_Kd g.png\nnewmtl glass\nillum 7\nmap_Kd x.png\n"
        "newmtl plastic\nKd 0.5\nKs 0.04\nmap_Kd p.png\nnewmtl gold\nKd 1 0.8 0.3\nPm 1\nmap_Kd au.png\n");
    ASSERT_EQ(p.warnings.size(), 1u) << joined(p.warnings);
    EXPECT_EQ(p.warnings[0],
              "t.mtl: ignored map_Kd of 2 metal or glass materials (only Lambertian, plastic and "
              "metallic-roughness materials have a diffuse colour) (first at line 4)");
    ASSERT_EQ(p.materials.size(), 4u);
    EXPECT_EQ(p.materials[0].diffuseTexture, -1);
    EXPECT_EQ(p.materials[1].diffuseTexture, -1);
    EXPECT_EQ(p.materials[2].type, MaterialType::Plastic);
    EXPECT_EQ(p.materials[2].diffuseTexture, 0);
    // A metallic-roughness metal's base colour is its F0: the map multiplies it.
    EXPECT_EQ(p.materials[3].type, MaterialType::MetallicRoughness);
    EXPECT_EQ(p.materials[3].diffuseTexture, 1);
    ASSERT_EQ(p.textures.size(), 2u);
    EXPECT_EQ(p.textures[0].file, "p.png");
    EXPECT_EQ(p.textures[1].file, "au.png");
}

}  // namespace
}  // namespace fp
