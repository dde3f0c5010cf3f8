// The caustic casters' spheres (src/pack/caustic_casters.h): nee's light pass sends light paths only
// into the cones they subtend, so a caster vertex outside every sphere would lose its caustic (the camera
// pass leaves it to the light pass): every vertex of every material with a delta lobe must be inside one.
#include <gtest/gtest.h>

#include <random>

#include "pack/caustic_casters.h"
#include "scene/procedural.h"

namespace fp {
namespace {

Material material(MaterialType type, float roughness) {
    Material m;
    m.type = type;
    m.roughness = roughness;
    return m;
}

// A 2x1 metallic-roughness map whose G channel (the roughness factor's scale) is g0, g1 over 255.
Texture roughnessMap(uint8_t g0, uint8_t g1) {
    Texture map;
    map.image.width = 2;
    map.image.height = 1;
    map.image.texels = {0, g0, 0, 255, 0, g1, 0, 255};
    return map;
}

bool insideSome(const std::vector<glm::vec4>& spheres, const glm::vec3& p) {
    for (const glm::vec4& s : spheres)
        if (glm::length(p - glm::vec3(s)) <= s.w * (1.0f + 1e-5f) + 1e-6f) return true;
    return false;
}

TEST(CausticCasters, DeltaLobesAreSmoothSpecularLobesOrMappedOnesThatReachSmooth) {
    const std::vector<Texture> none;
    EXPECT_FALSE(hasDeltaLobe(material(MaterialType::Diffuse, 0.0f), none));
    EXPECT_TRUE(hasDeltaLobe(material(MaterialType::Dielectric, 0.0f), none));
    EXPECT_FALSE(hasDeltaLobe(material(MaterialType::Dielectric, 0.3f), none));
    EXPECT_TRUE(hasDeltaLobe(material(MaterialType::Conductor, 0.005f), none));
    EXPECT_TRUE(hasDeltaLobe(material(MaterialType::Plastic, 0.0f), none));
    EXPECT_FALSE(hasDeltaLobe(material(MaterialType::MetallicRoughness, 0.5f), none));
    EXPECT_FALSE(hasDeltaLobe(material(MaterialType::Unlit, 0.0f), none)) << "it scatters nothing";
    // A smooth clearcoat (KHR_materials_clearcoat) is a mirror over any base; a rough one is not.
    Material coated = material(MaterialType::MetallicRoughness, 0.5f);
    coated.clearcoat = 0.5f;
    EXPECT_TRUE(hasDeltaLobe(coated, none));
    coated.clearcoatRoughness = 0.3f;
    EXPECT_FALSE(hasDeltaLobe(coated, none));
    // A roughness map scales the factor by its G channel: by 128/255 everywhere it stays rough; one
    // texel of G 1 takes it to 0.004, smooth.
    Material mapped = material(MaterialType::MetallicRoughness, 1.0f);
    mapped.metallicRoughnessTexture = 0;
    EXPECT_FALSE(hasDeltaLobe(mapped, {roughnessMap(128, 128)}));
    EXPECT_TRUE(hasDeltaLobe(mapped, {roughnessMap(128, 1)}));
    EXPECT_TRUE(hasDeltaLobe(mapped, none)) << "a map that is not there";
}

TEST(CausticCasters, GlossyCastersAreMetalsBelowTheRoughnessThreshold) {
    const std::vector<Texture> none;
    const float below = 0.9f * kGlossyCasterRoughness, above = kGlossyCasterRoughness + 0.05f;
    EXPECT_TRUE(isGlossyCasterMaterial(material(MaterialType::Conductor, below), none));
    EXPECT_FALSE(isGlossyCasterMaterial(material(MaterialType::Conductor, above), none));
    EXPECT_FALSE(isGlossyCasterMaterial(material(MaterialType::Plastic, below), none)) << "a diffuse base";
    EXPECT_FALSE(isGlossyCasterMaterial(material(MaterialType::Dielectric, below), none));
    EXPECT_FALSE(isGlossyCasterMaterial(material(MaterialType::Diffuse, 0.0f), none));
    Material metal = material(MaterialType::MetallicRoughness, below);
    metal.metallic = 1.0f;
    EXPECT_TRUE(isGlossyCasterMaterial(metal, none));
    metal.metallic = 0.5f;
    EXPECT_FALSE(isGlossyCasterMaterial(metal, none)) << "part plastic";
    // A roughness map that takes a rough factor below the threshold somewhere.
    Material mapped = material(MaterialType::Conductor, 1.0f);
    mapped.metallicRoughnessTexture = 0;
    EXPECT_FALSE(isGlossyCasterMaterial(mapped, {roughnessMap(255, 255)}));
    EXPECT_TRUE(isGlossyCasterMaterial(mapped, {roughnessMap(255, 20)}));
}

// Twelve caster materials scattered over a room (more than kMaxCausticCasters: merged), diffuse ones
// among them, and an instanced glass mesh placed twice.
TEST(CausticCasters, EveryCasterVertexIsInsideASphere) {
    Scene scene;
    scene.materials.push_back(material(MaterialType::Diffuse, 0.0f));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    for (int i = 0; i < 24; ++i) {
        uint32_t m = uint32_t(scene.materials.size());
        scene.materials.push_back(i % 2 ? material(MaterialType::Dielectric, 0.0f)
                                        : material(MaterialType::Diffuse, 0.0f));
        appendSphere(scene, glm::vec3(u(rng), u(rng), u(rng)), 0.2f + 0.05f * float(i % 5), 6, 12, m, true);
    }
    InstancedMesh mesh;
    mesh.name = "glass ball";
    Scene ball;
    appendSphere(ball, glm::vec3(0.0f), 1.0f, 6, 12, 2, true);  // material 2: glass
    mesh.triangles = ball.triangles;
    scene.meshes.push_back(mesh);
    Instance a, b;
    a.objectToWorld = glm::mat4(2.0f);
    a.objectToWorld[3] = glm::vec4(20.0f, 0.0f, 0.0f, 1.0f);
    b.objectToWorld[3] = glm::vec4(-20.0f, 3.0f, 1.0f, 1.0f);
    scene.instances = {a, b};

    std::vector<glm::vec4> spheres = causticCasterSpheres(scene);
    ASSERT_FALSE(spheres.empty());
    EXPECT_LE(spheres.size(), size_t(kMaxCausticCasters));
    int casterVertices = 0;
    for (const Triangle& t : scene.triangles)
        if (hasDeltaLobe(scene.materials[t.material], scene.textures))
            for (const glm::vec3& p : t.p) {
                EXPECT_TRUE(insideSome(spheres, p)) << p.x << " " << p.y << " " << p.z;
                ++casterVertices;
            }
    for (const Instance& instance : scene.instances)
        for (const Triangle& t : mesh.triangles)
            for (const glm::vec3& p : t.p) {
                glm::vec3 placed = glm::vec3(instance.objectToWorld * glm::vec4(p, 1.0f));
                EXPECT_TRUE(insideSome(spheres, placed)) << placed.x << " " << placed.y << " " << placed.z;
                ++casterVertices;
            }
    EXPECT_GT(casterVertices, 1000);
}

// Start-up had grown with triangles x texels: a material's roughness map was read for every one of its
// triangles. Now each map is read once, whatever the number of triangles and materials sharing it, and
// not at all for a material that cannot be a caster (Lambertian).
TEST(CausticCasters, EachRoughnessMapIsReadOnceHoweverManyTrianglesShareIt) {
    Scene scene;
    // Maps: 0 reaches roughness 0.08 at one texel (glossy for a metal); 1 stays rough; 2 is on a
    // Lambertian material only.
    scene.textures = {roughnessMap(255, 20), roughnessMap(255, 255), roughnessMap(0, 0)};
    for (int i = 0; i < 3; ++i) {  // three metals sharing map 0
        Material metal = material(MaterialType::MetallicRoughness, 1.0f);
        metal.metallic = 1.0f;
        metal.metallicRoughnessTexture = 0;
        scene.materials.push_back(metal);
    }
    Material rough = material(MaterialType::Conductor, 1.0f);
    rough.metallicRoughnessTexture = 1;
    scene.materials.push_back(rough);  // 3
    Material lambertian = material(MaterialType::Diffuse, 1.0f);
    lambertian.metallicRoughnessTexture = 2;
    scene.materials.push_back(lambertian);  // 4
    for (uint32_t m = 0; m < 5; ++m)
        appendSphere(scene, glm::vec3(4.0f * float(m), 0.0f, 0.0f), 1.0f, 12, 24, m, true);
    ASSERT_GT(scene.triangles.size(), 2000u);

    size_t mapsRead = 0;
    std::vector<glm::vec4> spheres = causticCasterSpheres(scene, &mapsRead);
    EXPECT_EQ(mapsRead, 2u) << "maps 0 and 1, once each";
    // The three metals are casters (and only they: the rough conductor's sphere at x = 12 would reach
    // past x = 11).
    ASSERT_FALSE(spheres.empty());
    for (const Triangle& t : scene.triangles)
        for (const glm::vec3& p : t.p)
            EXPECT_EQ(insideSome(spheres, p), t.material < 3) << p.x << " " << p.y << " " << p.z;
}

TEST(CausticCasters, NoneWithoutADeltaLobe) {
    Scene scene;
    scene.materials = {material(MaterialType::Diffuse, 0.0f), material(MaterialType::Dielectric, 0.4f)};
    appendSphere(scene, glm::vec3(0.0f), 1.0f, 6, 12, 0, true);
    appendSphere(scene, glm::vec3(3.0f), 1.0f, 6, 12, 1, true);
    EXPECT_TRUE(causticCasterSpheres(scene).empty());
}

}  // namespace
}  // namespace fp
