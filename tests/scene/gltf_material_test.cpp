// glTF materials onto fragpath's, rule by rule as the README's material table gives them, and the
// warnings for what they cannot hold.
#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "image/tone_map.h"
#include "scene/load.h"
#include "scene_test_util.h"
#include "texture_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;
using test::GltfBuilder;

// A quad in z = 0 facing +z (uv per corner), as two triangles.
json quadPrimitive(GltfBuilder& b, int material, bool texcoords = true, const char* set = "TEXCOORD_0") {
    json attributes = {{"POSITION", b.vec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})}};
    if (texcoords) attributes[set] = b.vec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    json p = {{"attributes", attributes}, {"indices", b.indices16({0, 1, 2, 0, 2, 3})}};
    if (material >= 0) p["material"] = material;
    return p;
}

// One quad per material (and one without a material when `withDefault`), loaded from a .gltf.
Scene withMaterials(GltfBuilder& b, const std::vector<json>& materials, bool withDefault = false) {
    json primitives = json::array();
    for (const json& m : materials) primitives.push_back(quadPrimitive(b, b.material(m)));
    if (withDefault) primitives.push_back(quadPrimitive(b, -1));
    b.mesh(primitives);
    b.node({{"mesh", int(b.doc["meshes"].size()) - 1}});
    b.scene({0});
    test::TempDir dir;
    return loadScene(dir.write("m.gltf", b.gltf()));
}

const Material& materialOfQuad(const Scene& scene, size_t quad) {
    return scene.materials[scene.triangles.at(2 * quad).material];
}

json pbr(double metallic, double roughness, json extra = json::object()) {
    json p = {{"metallicFactor", metallic}, {"roughnessFactor", roughness}};
    p.update(extra);
    return p;
}

TEST(GltfMaterial, TheTablesRulesInOrder) {
    GltfBuilder b;
    json color = {0.2, 0.4, 0.6, 1.0};
    WarningCapture capture;
    Scene scene = withMaterials(
        b,
        {
            json::object(),                                                         // 0: all defaults
            {{"pbrMetallicRoughness", pbr(0, 1, {{"baseColorFactor", color}})}},    // 1
            {{"pbrMetallicRoughness", pbr(0, 0.3, {{"baseColorFactor", color}})}},  // 2
            {{"pbrMetallicRoughness", pbr(0, 0.3)},                                 // 3
             {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}},
            {{"pbrMetallicRoughness", pbr(0, 0.3)},  // 4
             {"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}}}}},
            {{"pbrMetallicRoughness", pbr(0.8, 0.2, {{"baseColorFactor", {1.0, 0.8, 0.3, 1.0}}})}},  // 5
            {{"pbrMetallicRoughness", pbr(0.4, 0.2)}},                                               // 6
            {{"pbrMetallicRoughness", pbr(0, 0, {{"baseColorFactor", {0.9, 1.0, 0.9, 1.0}}})},       // 7
             {"extensions",
              {{"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
               {"KHR_materials_ior", {{"ior", 1.7}}}}}},
            {{"pbrMetallicRoughness", pbr(0, 1)},  // 8
             {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}}},
            {{"pbrMetallicRoughness", pbr(1, 0.1)},  // 9
             {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}},
            {{"pbrMetallicRoughness", pbr(0, 1)},  // 10
             {"emissiveFactor", {1.0, 0.5, 0.25}},
             {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
            {{"pbrMetallicRoughness", pbr(0, 1, {{"baseColorFactor", {1, 1, 1, 0.25}}})},  // 11
             {"alphaMode", "MASK"},
             {"alphaCutoff", 0.2},
             {"doubleSided", true}},
            {{"pbrMetallicRoughness", pbr(0, 1, {{"baseColorFactor", {1, 1, 1, 0.25}}})},  // 12
             {"alphaMode", "BLEND"}},
        },
        true);
    // The model holds all of it.
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);

    // No properties: glTF's defaults, metallic 1 and roughness 1, a white rough metal, single-sided.
    const Material& defaults = materialOfQuad(scene, 0);
    EXPECT_EQ(defaults.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(defaults.diffuse, glm::vec3(1.0f));
    EXPECT_EQ(defaults.metallic, 1.0f);
    EXPECT_EQ(defaults.roughness, 1.0f);
    EXPECT_FALSE(defaults.doubleSided);
    EXPECT_EQ(defaults.alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(defaults.name, "materials[0]");

    // Every other material is the same model with its factors: base colour, metallic, roughness, and
    // the coat's index from KHR_materials_ior (1.5 without).
    const Material& dielectric = materialOfQuad(scene, 2);
    EXPECT_EQ(dielectric.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(dielectric.diffuse, glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_EQ(dielectric.metallic, 0.0f);
    EXPECT_FLOAT_EQ(dielectric.roughness, 0.3f);
    EXPECT_EQ(dielectric.ior, 1.5f);
    EXPECT_EQ(materialOfQuad(scene, 1).roughness, 1.0f);
    EXPECT_EQ(materialOfQuad(scene, 3).type, MaterialType::MetallicRoughness);
    EXPECT_EQ(materialOfQuad(scene, 3).specularColor, glm::vec3(0.0f));  // KHR_materials_specular
    EXPECT_EQ(dielectric.specularColor, glm::vec3(1.0f));                // without it: the plain coat
    EXPECT_FLOAT_EQ(materialOfQuad(scene, 4).ior, 1.33f);
    const Material& metal = materialOfQuad(scene, 5);
    EXPECT_EQ(metal.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(metal.diffuse, glm::vec3(1.0f, 0.8f, 0.3f));
    EXPECT_FLOAT_EQ(metal.metallic, 0.8f);
    EXPECT_FLOAT_EQ(metal.roughness, 0.2f);
    EXPECT_FLOAT_EQ(materialOfQuad(scene, 6).metallic, 0.4f);

    // Transmission through more than half the surface (the dielectric part, 1 - metallic) is glass.
    const Material& glass = materialOfQuad(scene, 7);
    EXPECT_EQ(glass.type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(glass.ior, 1.7f);
    EXPECT_EQ(glass.transmission, glm::vec3(0.9f, 1.0f, 0.9f));
    EXPECT_EQ(glass.roughness, 0.0f);
    EXPECT_EQ(materialOfQuad(scene, 8).type, MaterialType::MetallicRoughness);  // 0.5 is not above it
    EXPECT_EQ(materialOfQuad(scene, 9).type, MaterialType::MetallicRoughness);  // a metal transmits nothing

    const Material& lamp = materialOfQuad(scene, 10);
    EXPECT_EQ(lamp.emission, glm::vec3(4.0f, 2.0f, 1.0f));

    const Material& masked = materialOfQuad(scene, 11);
    EXPECT_EQ(masked.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(masked.alpha, 0.25f);
    EXPECT_FLOAT_EQ(masked.alphaCutoff, 0.2f);
    EXPECT_TRUE(masked.doubleSided);
    const Material& blended = materialOfQuad(scene, 12);
    EXPECT_EQ(blended.alphaMode, AlphaMode::Blend);
    EXPECT_EQ(blended.alpha, 0.25f);

    // A primitive without a material: the glTF default material, added once.
    const Material& none = materialOfQuad(scene, 13);
    EXPECT_EQ(none.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(none.metallic, 1.0f);
    EXPECT_EQ(none.name, "glTF default");
    EXPECT_EQ(scene.materials.size(), 14u);
}

TEST(GltfMaterial, EmissiveQuad) {
    GltfBuilder b;
    Scene scene = withMaterials(
        b, {{{"name", "lamp"},
             {"pbrMetallicRoughness", pbr(0, 1, {{"baseColorFactor", {0, 0, 0, 1}}})},
             {"emissiveFactor", {1.0, 1.0, 1.0}},
             {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 17}}}}}}});
    ASSERT_EQ(scene.triangles.size(), 2u);
    for (const Triangle& t : scene.triangles) {
        const Material& m = scene.materials[t.material];
        EXPECT_EQ(m.name, "lamp");
        EXPECT_TRUE(m.isEmissive());
        EXPECT_EQ(m.emission, glm::vec3(17.0f));
        EXPECT_EQ(m.diffuse, glm::vec3(0.0f));
        // It emits from its front, +z, where the quad's counter-clockwise winding faces.
        EXPECT_GT(t.geometricNormal().z, 0.0f);
    }
}

TEST(GltfMaterial, IorOutsideTheModelsRangeIsClampedWithAWarning) {
    GltfBuilder b;
    WarningCapture capture;
    Scene scene = withMaterials(b, {{{"name", "diamondish"},
                                     {"pbrMetallicRoughness", pbr(0, 0)},
                                     {"extensions",
                                      {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                       {"KHR_materials_ior", {{"ior", 6.0}}}}}}});
    EXPECT_EQ(materialOfQuad(scene, 0).ior, 4.0f);
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "m.gltf: KHR_materials_ior outside [1, 4] clamped",
                        "material 'diamondish' (materials[0])");
}

// A texture in a data URI: images[i] and textures[i] for each call.
int addTexture(GltfBuilder& b, const std::vector<uint8_t>& rgba, int width, int height) {
    b.push("images", {{"uri", "data:image/png;base64," + test::base64(test::pngBytes(width, height, rgba))}});
    return b.push("textures", {{"source", int(b.doc["images"].size()) - 1}});
}

// KHR_materials_unlit: the base colour shown as it is, not a light (no emission, whatever the file says),
// its alpha kept; the maps of lighting (metallic-roughness, emission, normals) dropped.
TEST(GltfMaterial, UnlitShowsItsBaseColourAndIsNoLight) {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_materials_unlit"};  // implemented: no "ignoring extensions" warning
    WarningCapture capture;
    Scene scene =
        withMaterials(b, {{{"pbrMetallicRoughness", pbr(1, 0.2, {{"baseColorFactor", {1, 0.5, 0, 0.5}}})},
                           {"emissiveFactor", {1.0, 1.0, 1.0}},
                           {"alphaMode", "BLEND"},
                           {"extensions", {{"KHR_materials_unlit", json::object()}}}}});
    const Material& unlit = materialOfQuad(scene, 0);
    EXPECT_EQ(unlit.type, MaterialType::Unlit);
    EXPECT_EQ(unlit.diffuse, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_FALSE(unlit.isEmissive());
    EXPECT_EQ(unlit.alpha, 0.5f);
    EXPECT_EQ(unlit.alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

// KHR_materials_specular: specularFactor * specularColorFactor tints the coat, clamped to 1 with a
// warning; its textures' means multiply the factors (A of specularTexture, the linear RGB of
// specularColorTexture), with a warning that says so.
TEST(GltfMaterial, SpecularFactorsTintTheCoat) {
    GltfBuilder b;
    int alpha = addTexture(b, {0, 0, 0, 255, 0, 0, 0, 51}, 2, 1);          // A: mean (1 + 0.2) / 2 = 0.6
    int colour = addTexture(b, {255, 255, 255, 255, 0, 0, 0, 255}, 2, 1);  // RGB: mean 0.5 (linear)
    WarningCapture capture;
    Scene scene = withMaterials(
        b,
        {{{"pbrMetallicRoughness", pbr(0, 0.5)},
          {"extensions",
           {{"KHR_materials_specular",
             {{"specularFactor", 0.5}, {"specularColorFactor", {1.0, 0.5, 0.25}}}}}}},
         {{"name", "bright"},
          {"pbrMetallicRoughness", pbr(0, 0.5)},
          {"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {2.0, 0.5, 0.5}}}}}}},
         {{"name", "mapped"},
          {"pbrMetallicRoughness", pbr(0, 0.5)},
          {"extensions",
           {{"KHR_materials_specular",
             {{"specularTexture", {{"index", alpha}}}, {"specularColorTexture", {{"index", colour}}}}}}}}});
    EXPECT_EQ(materialOfQuad(scene, 0).specularColor, glm::vec3(0.5f, 0.25f, 0.125f));
    EXPECT_EQ(materialOfQuad(scene, 1).specularColor, glm::vec3(1.0f, 0.5f, 0.5f));
    glm::vec3 mapped = materialOfQuad(scene, 2).specularColor;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mapped[c], 0.6f * 0.5f, 1e-3f) << c;
    std::string all = test::joined(capture);
    EXPECT_CONTAINS_ALL(
        all, "specularFactor * specularColorFactor above 1 clamped to 1 (material 'bright'",
        "KHR_materials_specular textures: the factors are multiplied by their means (material "
        "'mapped'");
}

// KHR_materials_clearcoat: the factor and the coat's roughness (times their textures' means: R of
// clearcoatTexture, G of clearcoatRoughnessTexture), on the metallic-roughness model; its normal map is
// warned about, and so is a clearcoat on glass, which has none.
TEST(GltfMaterial, ClearcoatFactorsAndTheirTexturesMeans) {
    GltfBuilder b;
    int map = addTexture(b, {255, 255, 0, 255, 51, 0, 0, 255}, 2, 1);  // R mean 0.6, G mean 0.5
    WarningCapture capture;
    Scene scene = withMaterials(
        b, {{{"pbrMetallicRoughness", pbr(0, 0.5)},
             {"extensions",
              {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.8}, {"clearcoatRoughnessFactor", 0.1}}}}}},
            {{"name", "mapped"},
             {"pbrMetallicRoughness", pbr(1, 0.5)},
             {"extensions",
              {{"KHR_materials_clearcoat",
                {{"clearcoatFactor", 1.0},
                 {"clearcoatRoughnessFactor", 0.4},
                 {"clearcoatTexture", {{"index", map}}},
                 {"clearcoatRoughnessTexture", {{"index", map}}},
                 {"clearcoatNormalTexture", {{"index", map}}}}}}}},
            {{"name", "glass"},
             {"pbrMetallicRoughness", pbr(0, 0)},
             {"extensions",
              {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
               {"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}}}},
            {{"pbrMetallicRoughness", pbr(0, 0.5)}}});
    EXPECT_FLOAT_EQ(materialOfQuad(scene, 0).clearcoat, 0.8f);
    EXPECT_FLOAT_EQ(materialOfQuad(scene, 0).clearcoatRoughness, 0.1f);
    EXPECT_NEAR(materialOfQuad(scene, 1).clearcoat, 0.6f, 1e-3f);
    EXPECT_NEAR(materialOfQuad(scene, 1).clearcoatRoughness, 0.2f, 1e-3f);
    EXPECT_EQ(materialOfQuad(scene, 2).clearcoat, 0.0f);
    EXPECT_EQ(materialOfQuad(scene, 3).clearcoat, 0.0f);
    EXPECT_CONTAINS_ALL(
        test::joined(capture),
        "KHR_materials_clearcoat textures: the factors are multiplied by their means (material "
        "'mapped'",
        "clearcoatNormalTexture ignored", "KHR_materials_clearcoat on glass ignored (material 'glass'");
}

// KHR_materials_sheen: the colour and roughness factors (times their textures' means: the linear RGB of
// sheenColorTexture, A of sheenRoughnessTexture) on the metallic-roughness model.
TEST(GltfMaterial, SheenFactorsAndTheirTexturesMeans) {
    GltfBuilder b;
    int map = addTexture(b, {255, 255, 255, 255, 0, 0, 0, 51}, 2, 1);  // RGB mean 0.5 (linear), A mean 0.6
    WarningCapture capture;
    Scene scene =
        withMaterials(b, {{{"pbrMetallicRoughness", pbr(0, 0.5)},
                           {"extensions",
                            {{"KHR_materials_sheen",
                              {{"sheenColorFactor", {1.0, 0.5, 0.25}}, {"sheenRoughnessFactor", 0.3}}}}}},
                          {{"name", "mapped"},
                           {"pbrMetallicRoughness", pbr(0, 0.5)},
                           {"extensions",
                            {{"KHR_materials_sheen",
                              {{"sheenColorFactor", {1.0, 1.0, 1.0}},
                               {"sheenRoughnessFactor", 1.0},
                               {"sheenColorTexture", {{"index", map}}},
                               {"sheenRoughnessTexture", {{"index", map}}}}}}}},
                          {{"pbrMetallicRoughness", pbr(0, 0.5)}}});
    EXPECT_EQ(materialOfQuad(scene, 0).sheenColor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(materialOfQuad(scene, 0).sheenRoughness, 0.3f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(materialOfQuad(scene, 1).sheenColor[c], 0.5f, 1e-3f) << c;
    EXPECT_NEAR(materialOfQuad(scene, 1).sheenRoughness, 0.6f, 1e-3f);
    EXPECT_EQ(materialOfQuad(scene, 2).sheenColor, glm::vec3(0.0f));
    EXPECT_CONTAINS_ALL(
        test::joined(capture),
        "KHR_materials_sheen textures: the factors are multiplied by their means (material 'mapped'");
}

// KHR_materials_volume on glass: sigma_a = -ln(attenuationColor) / attenuationDistance per unit length;
// none for a thin-walled material (thicknessFactor 0, the default), an infinite distance (the default),
// or a material that is not glass.
TEST(GltfMaterial, VolumeAttenuationIsTheAbsorptionCoefficient) {
    GltfBuilder b;
    auto glass = [](json volume) {
        return json{{"pbrMetallicRoughness", pbr(0, 0)},
                    {"extensions",
                     {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                      {"KHR_materials_volume", volume}}}};
    };
    json tinted = {
        {"thicknessFactor", 1.0}, {"attenuationColor", {0.5, 0.25, 1.0}}, {"attenuationDistance", 2.0}};
    json opaque = {{"pbrMetallicRoughness", pbr(0, 0.5)}, {"extensions", {{"KHR_materials_volume", tinted}}}};
    Scene scene = withMaterials(
        b,
        {glass(tinted), glass({{"attenuationColor", {0.5, 0.5, 0.5}}, {"attenuationDistance", 2.0}}),
         glass({{"thicknessFactor", 1.0}, {"attenuationColor", {0.5, 0.5, 0.5}}}),
         glass(
             {{"thicknessFactor", 1.0}, {"attenuationColor", {0.0, 1.0, 1.0}}, {"attenuationDistance", 1.0}}),
         opaque});
    const Material& absorbing = materialOfQuad(scene, 0);
    EXPECT_EQ(absorbing.type, MaterialType::Dielectric);
    EXPECT_FLOAT_EQ(absorbing.absorption.r, std::log(2.0f) / 2.0f);
    EXPECT_FLOAT_EQ(absorbing.absorption.g, std::log(4.0f) / 2.0f);
    EXPECT_EQ(absorbing.absorption.b, 0.0f);
    EXPECT_EQ(materialOfQuad(scene, 1).absorption, glm::vec3(0.0f));  // thin-walled
    EXPECT_EQ(materialOfQuad(scene, 2).absorption, glm::vec3(0.0f));  // attenuationDistance infinite
    EXPECT_EQ(materialOfQuad(scene, 3).absorption, glm::vec3(1e4f, 0.0f, 0.0f));  // black: absorbs all
    EXPECT_EQ(materialOfQuad(scene, 4).absorption, glm::vec3(0.0f));              // not glass
}

// Every map becomes the model's texture of that kind; the base colour texture's alpha is the coverage
// map of MASK and BLEND materials. Glass takes its base colour and metallic-roughness maps' means.
TEST(GltfMaterial, MapsAreTheModelsTexturesAndGlassTakesTheirMeans) {
    GltfBuilder b;
    int flat = addTexture(b, test::checkerTexels(1, 1, {128, 128, 255}, {128, 128, 255}), 1, 1);
    // Blue (metallic) 0 and 102, green (roughness) 51 and 153.
    int mr = addTexture(b, test::checkerTexels(2, 1, {0, 51, 0}, {0, 153, 102}), 2, 1);
    std::vector<uint8_t> checkerTexels = test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255});
    int checker = addTexture(b, checkerTexels, 2, 2);
    json textured = {{"baseColorTexture", {{"index", checker}}},
                     {"metallicRoughnessTexture", {{"index", mr}}}};
    // Unused materials warn about nothing (and their textures are never loaded).
    b.material({{"name", "unused"}, {"occlusionTexture", {{"index", flat}}}});
    WarningCapture capture;
    Scene scene = withMaterials(
        b, {{{"name", "brick"},
             {"pbrMetallicRoughness", pbr(1, 1, textured)},
             {"normalTexture", {{"index", flat}, {"scale", 0.5}}},
             {"emissiveTexture", {{"index", checker}}},
             {"emissiveFactor", {1, 1, 1}}},
            {{"name", "stone"}, {"pbrMetallicRoughness", pbr(0, 1)}, {"occlusionTexture", {{"index", flat}}}},
            {{"name", "leaf"}, {"pbrMetallicRoughness", pbr(0, 1, textured)}, {"alphaMode", "MASK"}},
            {{"name", "window"},
             {"pbrMetallicRoughness", pbr(0, 1, textured)},
             {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}}});
    ASSERT_EQ(scene.textures.size(), 3u) << "each image once";
    const Material& brick = materialOfQuad(scene, 0);
    EXPECT_EQ(brick.type, MaterialType::MetallicRoughness);
    ASSERT_GE(brick.diffuseTexture, 0);
    EXPECT_EQ(scene.textures[size_t(brick.diffuseTexture)].image.texels, checkerTexels);
    EXPECT_GE(brick.metallicRoughnessTexture, 0);
    EXPECT_EQ(brick.emissionTexture, brick.diffuseTexture);
    EXPECT_GE(brick.normalTexture, 0);
    EXPECT_EQ(brick.normalScale, 0.5f);
    EXPECT_EQ(brick.alphaTexture, -1) << "opaque";
    EXPECT_EQ(brick.metallic, 1.0f) << "the factors stay: the maps multiply them";
    EXPECT_EQ(brick.roughness, 1.0f);
    const Material& leaf = materialOfQuad(scene, 2);
    EXPECT_EQ(leaf.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(leaf.alphaTexture, leaf.diffuseTexture);
    const Material& window = materialOfQuad(scene, 3);
    EXPECT_EQ(window.type, MaterialType::Dielectric);
    EXPECT_FALSE(window.hasTextures());
    float red = srgbDecode(1.0f);
    EXPECT_NEAR(window.transmission.r, 0.5f * red, 1e-6f);
    EXPECT_NEAR(window.transmission.g, 0.0f, 1e-6f);
    EXPECT_NEAR(window.roughness, (51 + 153) / 510.0f, 1e-6f);
    std::string all = test::joined(capture);
    EXPECT_EQ(capture.messages().size(), 2u) << all;
    EXPECT_TRUE(capture.contains(
        "occlusionTexture ignored (a path tracer computes occlusion itself) (material 'stone'"))
        << all;
    EXPECT_TRUE(
        capture.contains("baseColorTexture and metallicRoughnessTexture on glass: their means used "
                         "(material 'window'"))
        << all;
    EXPECT_EQ(all.find("unused"), std::string::npos) << all;
}

// TANGENT reaches Scene::tangents for normal-mapped primitives, in world space: the tangent through
// the node's linear transform, w turned by a mirroring one (whose winding flip also reorders the
// corners); a normal-mapped primitive without TANGENT gets w = 0 (computed when packing), and a
// primitive without a normal map keeps none.
TEST(GltfMaterial, TangentsOfNormalMappedPrimitivesInWorldSpace) {
    GltfBuilder b;
    int flat = addTexture(b, test::checkerTexels(1, 1, {128, 128, 255}, {128, 128, 255}), 1, 1);
    int mapped = b.material({{"pbrMetallicRoughness", pbr(0, 1)}, {"normalTexture", {{"index", flat}}}});
    int plain = b.material({{"pbrMetallicRoughness", pbr(0, 1)}});
    auto withTangents = [&](int material) {
        json p = quadPrimitive(b, material);
        p["attributes"]["TANGENT"] = b.vec4({{1, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, -1}, {0, 1, 0, -1}});
        return p;
    };
    b.mesh(json::array({withTangents(mapped), quadPrimitive(b, mapped), withTangents(plain)}));
    // Mirrored in x, then turned a quarter about z: x -> -x -> -y... (rotation applies after scale).
    const double s = std::sqrt(0.5);
    b.node({{"mesh", 0}, {"scale", {-1, 1, 1}}, {"rotation", {0, 0, s, s}}});
    b.scene({0});
    test::TempDir dir;
    Scene scene = loadScene(dir.write("m.gltf", b.gltf()));
    ASSERT_EQ(scene.triangles.size(), 6u);
    ASSERT_EQ(scene.tangents.size(), 6u);
    // The quad's first triangle is corners (0, 1, 2), reordered (0, 2, 1) by the mirror. Tangent (1, 0,
    // 0) mirrors to (-1, 0, 0) and turns to (0, -1, 0); (0, 1, 0) turns to (-1, 0, 0); w flips sign.
    const std::array<glm::vec4, 3>& first = scene.tangents[0];
    auto near = [](const glm::vec4& x, const glm::vec4& y) {
        return glm::all(glm::lessThan(glm::abs(x - y), glm::vec4(1e-6f)));
    };
    EXPECT_TRUE(near(first[0], {0, -1, 0, -1})) << first[0].x << " " << first[0].y << " " << first[0].w;
    EXPECT_TRUE(near(first[1], {-1, 0, 0, 1})) << first[1].x << " " << first[1].y << " " << first[1].w;
    EXPECT_TRUE(near(first[2], {0, -1, 0, -1})) << first[2].x << " " << first[2].y << " " << first[2].w;
    for (size_t t = 2; t < 6; ++t)
        for (const glm::vec4& tangent : scene.tangents[t]) EXPECT_EQ(tangent.w, 0.0f) << "triangle " << t;
}

// KHR_texture_transform is baked into the triangles' texture coordinates, uv' = T R S (u, v, 1) in
// glTF's uv, then v flipped: scale (2, 3), a quarter turn counter-clockwise as seen on the image (v
// down: (x, y) -> (y, -x), the turn of the sample model TextureTransformTest, not the specification's
// GLSL listing) and offset (0.5, 0) take (u, v) to (0.5 + 3 v, -2 u), so ours are (0.5 + 3 v, 1 + 2 u).
// Its texCoord overrides the map's. A second map with another transform reads the second uv slot.
TEST(GltfMaterial, TextureTransformIsBakedIntoTheTexcoords) {
    GltfBuilder b;
    int checker = addTexture(b, test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255}), 2, 2);
    const double quarter = 1.5707963267948966;
    json transform = {{"offset", {0.5, 0.0}}, {"rotation", quarter}, {"scale", {2.0, 3.0}}};
    json base = {{"index", checker}, {"texCoord", 1}, {"extensions", {{"KHR_texture_transform", transform}}}};
    base["extensions"]["KHR_texture_transform"]["texCoord"] = 0;  // overrides texCoord 1
    json other = {{"index", checker}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.25, 0.0}}}}}}};
    WarningCapture capture;
    Scene scene = withMaterials(b, {{{"name", "transformed"},
                                     {"pbrMetallicRoughness", pbr(0, 1, {{"baseColorTexture", base}})},
                                     {"emissiveTexture", other}}});
    const Triangle& t = scene.triangles[0];  // corners with glTF uv (0, 1), (1, 1), (1, 0)
    const glm::vec2 expected[3] = {{3.5f, 1.0f}, {3.5f, 3.0f}, {0.5f, 3.0f}};
    const glm::vec2 second[3] = {{0.25f, 0.0f}, {1.25f, 0.0f}, {1.25f, 1.0f}};
    ASSERT_EQ(scene.texcoords1.size(), scene.triangles.size());
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(t.uv[size_t(k)].x, expected[k].x, 1e-5f) << "corner " << k;
        EXPECT_NEAR(t.uv[size_t(k)].y, expected[k].y, 1e-5f) << "corner " << k;
        EXPECT_NEAR(scene.texcoords1[0][size_t(k)].x, second[k].x, 1e-5f) << "corner " << k;
        EXPECT_NEAR(scene.texcoords1[0][size_t(k)].y, second[k].y, 1e-5f) << "corner " << k;
    }
    const Material& m = materialOfQuad(scene, 0);
    ASSERT_GE(m.diffuseTexture, 0);
    ASSERT_GE(m.emissionTexture, 0);
    EXPECT_EQ(scene.textures[size_t(m.diffuseTexture)].uvSlot, 0);
    EXPECT_EQ(scene.textures[size_t(m.emissionTexture)].uvSlot, 1);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);

    // A texCoord that names no set, and a non-finite transform, are refused.
    for (json bad : {json{{"texCoord", -1}}, json{{"texCoord", 1e300}}, json{{"texCoord", 0.5}},
                     json{{"scale", {1e308, 1e308}}, {"offset", {1e308, -1e308}}, {"rotation", 1e308}}}) {
        GltfBuilder c;
        int tex = addTexture(c, test::checkerTexels(1, 1, {9, 9, 9}, {9, 9, 9}), 1, 1);
        json info = {{"index", tex}, {"extensions", {{"KHR_texture_transform", bad}}}};
        std::string message = test::errorOf([&] {
            withMaterials(c, {{{"pbrMetallicRoughness", pbr(0, 1, {{"baseColorTexture", info}})}}});
        });
        EXPECT_NE(message.find("KHR_texture_transform"), std::string::npos) << bad.dump() << ": " << message;
    }
}

// A material's maps read at most two (TEXCOORD set, KHR_texture_transform) pairs; a map needing a third
// is replaced by its mean, with a warning: its factor keeps the map's average, not the full factor
// (emission 1 would make the surface glow white). Samplers' wrap modes and NEAREST reach the textures;
// one image under two samplers is two textures.
TEST(GltfMaterial, AThirdUvPairIsTheMapsMeanAndSamplersReachTheTextures) {
    GltfBuilder b;
    int checker = addTexture(b, test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255}), 2, 2);
    int mr = addTexture(b, test::checkerTexels(2, 1, {0, 51, 0}, {0, 153, 102}), 2, 1);
    int grey = addTexture(b, test::checkerTexels(1, 1, {128, 128, 128}, {128, 128, 128}), 1, 1);
    b.push("samplers", {{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}});
    int clamped = b.push("textures", {{"source", 0}, {"sampler", 0}});
    auto offset = [](double u) { return json{{"KHR_texture_transform", {{"offset", {u, 0.0}}}}}; };
    int three = b.material(
        {{"name", "three"},
         {"pbrMetallicRoughness", pbr(1, 1,
                                      {{"baseColorTexture", {{"index", checker}}},
                                       {"metallicRoughnessTexture", {{"index", mr}, {"texCoord", 1}}}})},
         {"emissiveFactor", {1, 1, 1}},
         {"emissiveTexture", {{"index", grey}, {"extensions", offset(0.5)}}}});
    int clampedMaterial =
        b.material({{"name", "clamped"},
                    {"pbrMetallicRoughness", pbr(0, 1, {{"baseColorTexture", {{"index", clamped}}}})}});
    json primitives = json::array();
    for (int m : {three, clampedMaterial}) {
        json p = quadPrimitive(b, m, true, "TEXCOORD_0");
        p["attributes"]["TEXCOORD_1"] = p["attributes"]["TEXCOORD_0"];
        primitives.push_back(p);
    }
    b.mesh(primitives);
    b.node({{"mesh", 0}});
    b.scene({0});
    test::TempDir dir;
    WarningCapture capture;
    Scene scene = loadScene(dir.write("m.gltf", b.gltf()));
    const Material& mapped = materialOfQuad(scene, 0);
    EXPECT_GE(mapped.diffuseTexture, 0);
    EXPECT_GE(mapped.metallicRoughnessTexture, 0);
    EXPECT_EQ(scene.textures[size_t(mapped.metallicRoughnessTexture)].uvSlot, 1);
    EXPECT_EQ(mapped.emissionTexture, -1);
    EXPECT_NEAR(mapped.emission.r, srgbDecode(128.0f / 255.0f), 1e-6f);  // the mean, not 1
    EXPECT_TRUE(
        capture.contains("maps needing a third pair of TEXCOORD set and KHR_texture_transform in one "
                         "material (two are drawn) replaced by their means (material 'three'"))
        << test::joined(capture);
    const Material& other = materialOfQuad(scene, 1);
    ASSERT_GE(other.diffuseTexture, 0);
    ASSERT_NE(other.diffuseTexture, mapped.diffuseTexture);
    const Texture& t = scene.textures[size_t(other.diffuseTexture)];
    EXPECT_EQ(t.wrapS, TextureWrap::ClampToEdge);
    EXPECT_EQ(t.wrapT, TextureWrap::MirroredRepeat);
    EXPECT_TRUE(t.nearest);
    EXPECT_EQ(scene.textures[size_t(mapped.diffuseTexture)].wrapS, TextureWrap::Repeat);
    EXPECT_FALSE(scene.textures[size_t(mapped.diffuseTexture)].nearest);
}

// COLOR_0 (glTF 2.0 3.7.2.1): VEC4 of normalized unsigned bytes and VEC3 of floats (alpha 1) per vertex in
// Scene::colors, 1 for a primitive without; an unnormalized integer accessor is refused, naming it.
TEST(GltfMaterial, VertexColoursReachTheScene) {
    GltfBuilder b;
    int m = b.material({{"pbrMetallicRoughness", pbr(0, 1)}});
    json bytes = quadPrimitive(b, m, false);
    std::vector<uint8_t> rgba = {255, 0, 0, 128, 0, 255, 0, 255, 0, 0, 255, 0, 51, 51, 51, 255};
    bytes["attributes"]["COLOR_0"] =
        b.accessor(GltfBuilder::raw(rgba), 5121, 4, "VEC4", {{"normalized", true}});
    json floats = quadPrimitive(b, m, false);
    floats["attributes"]["COLOR_0"] = b.vec3({{0.5f, 0.25f, 1.0f}, {0, 0, 0}, {1, 1, 1}, {0.2f, 0.2f, 0.2f}});
    b.mesh(json::array({bytes, floats, quadPrimitive(b, m, false)}));
    b.node({{"mesh", 0}});
    b.scene({0});
    test::TempDir dir;
    Scene scene = loadScene(dir.write("c.gltf", b.gltf()));
    ASSERT_EQ(scene.triangles.size(), 6u);
    ASSERT_EQ(scene.colors.size(), 6u);
    // The quad's triangles are corners (0, 1, 2) and (0, 2, 3).
    EXPECT_EQ(scene.colors[0][0], glm::vec4(1.0f, 0.0f, 0.0f, 128.0f / 255.0f));
    EXPECT_EQ(scene.colors[1][2], glm::vec4(0.2f, 0.2f, 0.2f, 1.0f));
    EXPECT_EQ(scene.colors[2][0], glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    for (const glm::vec4& c : scene.colors[5]) EXPECT_EQ(c, glm::vec4(1.0f));

    GltfBuilder c;
    int n = c.material({{"pbrMetallicRoughness", pbr(0, 1)}});
    json plain = quadPrimitive(c, n, false);
    plain["attributes"]["COLOR_0"] = c.accessor(GltfBuilder::raw(rgba), 5121, 4, "VEC4");
    c.mesh(json::array({plain}));
    c.node({{"mesh", 0}});
    c.scene({0});
    std::string message = test::errorOf([&] { loadScene(dir.write("bad.gltf", c.gltf())); });
    EXPECT_NE(
        message.find("COLOR_0 of meshes[0].primitives[0]) must be VEC3 or VEC4 of FLOAT, or of normalized"),
        std::string::npos)
        << message;
}

TEST(GltfMaterial, TexturedMaterialWithoutItsTexcoordsGetsTheMeanColour) {
    GltfBuilder b;
    int checker = addTexture(b, test::checkerTexels(2, 2, {255, 0, 0}, {0, 0, 255}), 2, 2);
    int m = b.material(
        {{"name", "tex"},
         {"pbrMetallicRoughness", pbr(0, 1,
                                      {{"baseColorFactor", {0.5, 0.5, 0.5, 1}},
                                       {"baseColorTexture", {{"index", checker}, {"texCoord", 1}}}})}});
    // Only the second quad has TEXCOORD_1, the set the texture reads; the first has TEXCOORD_0 only.
    b.mesh(json::array({quadPrimitive(b, m, true, "TEXCOORD_0"), quadPrimitive(b, m, true, "TEXCOORD_1")}));
    b.node({{"mesh", 0}});
    b.scene({0});
    test::TempDir dir;
    WarningCapture capture;
    Scene scene = loadScene(dir.write("m.gltf", b.gltf()));
    ASSERT_EQ(scene.triangles.size(), 4u);
    const Material& copy = materialOfQuad(scene, 0);
    EXPECT_EQ(copy.diffuseTexture, -1);
    float red = srgbDecode(1.0f);
    EXPECT_NEAR(copy.diffuse.r, 0.5f * 0.5f * red, 1e-6f);
    EXPECT_NEAR(copy.diffuse.g, 0.0f, 1e-6f);
    const Material& textured = materialOfQuad(scene, 1);
    EXPECT_EQ(textured.diffuseTexture, 0);
    EXPECT_EQ(scene.triangles[2].uv[0], glm::vec2(0.0f, 0.0f));  // TEXCOORD_1 (0, 1), flipped
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "primitives without the TEXCOORD_1 their maps need",
                        "material 'tex'");
}

TEST(GltfMaterial, OnlyUsedMaterialsLoadTheirTextures) {
    GltfBuilder b;
    b.push("images", {{"uri", "missing.png"}});
    b.push("textures", {{"source", 0}});
    b.material({{"name", "ghost"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    WarningCapture capture;
    Scene scene = withMaterials(b, {{{"pbrMetallicRoughness", pbr(0, 1)}}});
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

// As for a missing map_Kd: a warning (an error with --strict) and the magenta and black checker, with a
// base colour of 1 so that it shows as it is; a map that only stands in by its mean is ignored.
TEST(GltfMaterial, MissingOrBrokenImagesWarnAndShowTheChecker) {
    auto build = [] {
        GltfBuilder b;
        b.push("images", {{"uri", "missing.png"}});
        b.push("images", {{"uri", "data:image/png;base64,AAAA"}});  // three zero bytes: no PNG
        b.push("textures", {{"source", 0}});
        b.push("textures", {{"source", 1}});
        return b;
    };
    GltfBuilder b = build();
    WarningCapture capture;
    Scene scene = withMaterials(
        b, {{{"name", "ghost"},
             {"pbrMetallicRoughness",
              pbr(0, 1, {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"baseColorTexture", {{"index", 0}}}})}},
            {{"name", "garbled"},
             {"pbrMetallicRoughness", pbr(1, 0.5, {{"metallicRoughnessTexture", {{"index", 1}}}})}}});
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].image.texels, missingTextureChecker().texels);
    const Material& ghost = materialOfQuad(scene, 0);
    EXPECT_EQ(ghost.diffuseTexture, 0);
    EXPECT_EQ(ghost.diffuse, glm::vec3(1.0f));
    const Material& garbled = materialOfQuad(scene, 1);
    EXPECT_EQ(garbled.type, MaterialType::MetallicRoughness);
    EXPECT_EQ(garbled.metallicRoughnessTexture, -1);  // the factors alone
    EXPECT_EQ(garbled.roughness, 0.5f);
    ASSERT_EQ(capture.messages().size(), 2u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(
        capture.messages()[0],
        "m.gltf: 'ghost' (materials[0]): baseColorTexture: texture file 'missing.png' not found or "
        "unreadable (looked for ",
        "/missing.png); showing a magenta and black checker instead");
    EXPECT_CONTAINS_ALL(capture.messages()[1], "m.gltf: 'garbled' (materials[1]): metallicRoughnessTexture: ",
                        "images[1]: not an image stb_image can read", "; ignoring the map");

    GltfBuilder strict = build();
    setStrictWarnings(true);
    std::string message = test::errorOf([&] {
        withMaterials(strict,
                      {{{"pbrMetallicRoughness", pbr(0, 1, {{"baseColorTexture", {{"index", 0}}}})}}});
    });
    setStrictWarnings(false);
    EXPECT_CONTAINS_ALL(message, "texture file 'missing.png' not found", "(an error with --strict)");
}

}  // namespace
}  // namespace fp
