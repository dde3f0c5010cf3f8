// The packed GPU layout (src/pack/layout.h) read back on the CPU: every triangle reachable exactly
// once through the node links, boxes that contain what they point to, and a light CDF that ends at 1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "pack/layout.h"
#include "pack/pack.h"
#include "scene/light_selection.h"
#include "scene/punctual_light.h"

namespace fp {
namespace {

Scene randomScene(int triangles, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    Scene s;
    s.materials.resize(3);
    s.materials[1].emission = glm::vec3(4.0f, 2.0f, 1.0f);
    s.materials[2].emission = glm::vec3(1.0f);
    for (int i = 0; i < triangles; ++i) {
        Triangle t;
        glm::vec3 c(u(rng), u(rng), u(rng));
        for (auto& p : t.p) p = c + 0.1f * glm::vec3(u(rng), u(rng), u(rng));
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = {n, n, n};
        t.material = uint32_t(i % 3);
        s.triangles.push_back(t);
    }
    return s;
}

Bvh buildFor(const Scene& s) {
    AabbArray bounds;
    for (const Triangle& t : s.triangles) bounds.push_back(t.bounds());
    return buildBinnedSah(bounds);
}

layout::QuantisedNode nodeAt(const PackedScene& p, uint32_t i) {
    layout::QuantisedNode q;
    for (int k = 0; k < layout::kNodeTexels; ++k)
        q[size_t(k)] = p.nodes[size_t(i) * layout::kNodeTexels + size_t(k)];
    return q;
}

uint32_t linkOf(const PackedScene& p, uint32_t node, int slot) {
    return p.nodes[size_t(node) * layout::kNodeTexels + layout::kNodeLinkTexel][slot];
}

// Unpacks child `slot` (0 to 3) of node `i`: its quantised box.
Aabb childBounds(const PackedScene& p, uint32_t i, int slot) {
    layout::QuantisedBox q = layout::decodeChildBox(nodeAt(p, i), slot);
    Aabb b;
    // Rounded outwards to floats, so that containment below is never lost to the conversion.
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = float(q.lo[a]);
        if (double(b.lo[a]) > q.lo[a]) b.lo[a] = std::nextafter(b.lo[a], -INFINITY);
        b.hi[a] = float(q.hi[a]);
        if (double(b.hi[a]) < q.hi[a]) b.hi[a] = std::nextafter(b.hi[a], INFINITY);
    }
    return b;
}

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

Aabb packedTriangleBounds(const PackedScene& p, uint32_t i) {
    const glm::vec4* t = &p.triangles[size_t(i) * layout::kTriangleTexels];
    glm::vec3 v0(t[0]);
    Aabb b;
    b.grow(v0);
    b.grow(v0 + glm::vec3(t[1]));
    b.grow(v0 + glm::vec3(t[2]));
    return b;
}

// Walks the subtree of `node`, growing `reached` by the bounds of every triangle in it. Each child's
// (quantised) box must contain every triangle of its subtree; the boxes of a subtree need not nest, as
// each is rounded outwards on its own parent's grid.
void walk(const PackedScene& p, uint32_t node, std::vector<int>& visits, uint32_t& nodesSeen, Aabb& reached) {
    ++nodesSeen;
    ASSERT_LT(node, p.nodeCount);
    for (int side = 0; side < 4; ++side) {
        if (linkOf(p, node, side) == 0u) {
            // An empty slot: an inverted box (the traversal skips it by its link).
            Aabb box = childBounds(p, node, side);
            EXPECT_TRUE(box.empty()) << "node " << node << " slot " << side;
            continue;
        }
        layout::ChildLink link = layout::decodeChild(linkOf(p, node, side));
        uint32_t first = link.first, count = link.count;
        Aabb box = childBounds(p, node, side);
        Aabb subtree;
        if (count > 0) {
            for (uint32_t t = first; t < first + count; ++t) {
                ASSERT_LT(t, p.triangleCount);
                ++visits[t];
                // The packed v0 + e is recomputed, so allow one rounding of slack.
                Aabb tb = packedTriangleBounds(p, t);
                glm::vec3 slack = 1e-5f * (glm::abs(tb.lo) + glm::abs(tb.hi));
                tb.lo += slack;
                tb.hi -= slack;
                subtree.grow(tb);
            }
        } else {
            EXPECT_GT(first, node) << "children after their parent, and never the root";
            walk(p, first, visits, nodesSeen, subtree);
        }
        EXPECT_TRUE(contains(box, subtree)) << "node " << node << " side " << side;
        reached.grow(subtree);
    }
}

TEST(PackScene, EveryTriangleReachableOnceAndBoxesContainTheirContents) {
    for (int n : {1, 3, 4, 5, 100, 2000}) {
        Scene s = randomScene(n, uint32_t(n));
        PackedScene p = packScene(s, buildFor(s));
        ASSERT_EQ(p.triangles.size(), size_t(n) * layout::kTriangleTexels);
        ASSERT_EQ(p.nodes.size(), size_t(p.nodeCount) * layout::kNodeTexels);
        std::vector<int> visits(size_t(n), 0);
        uint32_t nodesSeen = 0;
        Aabb all;
        walk(p, 0, visits, nodesSeen, all);
        EXPECT_EQ(nodesSeen, p.nodeCount) << n << " triangles";
        for (int v : visits) EXPECT_EQ(v, 1) << n << " triangles";
    }
}

TEST(PackScene, LightCdfIsPowerProportionalAndEndsAtOne) {
    Scene s = randomScene(300, 7);
    PackedScene p = packScene(s, buildFor(s));
    ASSERT_EQ(p.lightCount, 200u);  // materials 1 and 2 emit
    double pmfSum = 0.0, previous = 0.0;
    float previousCdf = 0.0f;
    for (uint32_t e = 0; e < p.lightCount; ++e) {  // the cdf's entries (the light tree follows them)
        const glm::vec4& light = p.lights[e];
        uint32_t tri = uint32_t(light.x);
        ASSERT_EQ(float(tri), light.x) << "exact integer index";
        EXPECT_GT(light.y, previous);
        pmfSum += light.z;
        // The triangle's own texel carries the same pmf, for MIS when a BSDF ray hits it.
        EXPECT_EQ(p.triangles[size_t(tri) * layout::kTriangleTexels + 1].w, light.z);
        int material = int(p.triangles[size_t(tri) * layout::kTriangleTexels].w);
        glm::vec3 e1(p.triangles[size_t(tri) * 3 + 1]), e2(p.triangles[size_t(tri) * 3 + 2]);
        float area = 0.5f * glm::length(glm::cross(e1, e2));
        float power = luminance(s.materials[size_t(material)].emission) * area;
        EXPECT_NEAR(light.z, power / p.totalLightPower, 1e-5);
        EXPECT_EQ(light.y, previousCdf + light.z) << "the cdf is the running sum of the pmfs";
        previous = previousCdf = light.y;
    }
    EXPECT_NEAR(pmfSum, 1.0, 1e-5);
    EXPECT_EQ(p.lights[p.lightCount - 1].y, 1.0f);
}

// The packer puts the light tree (pack/light_tree.h) after the light table and each emitter's entry in
// its first normal's w, which the shader's MIS density reads (glsl/common/light_tree.glsl
// lightEntryOf): entry e's triangle must be the one whose normal says e, and e's leaf must hold it.
TEST(PackScene, LightTreeEntriesPointBackToTheirTriangles) {
    Scene s = randomScene(30, 4);
    PackedScene p = packScene(s, buildFor(s));
    ASSERT_EQ(p.lightCount, 20u);  // materials 1 and 2 emit
    EXPECT_EQ(p.lightTreeFirst, p.lightCount) << "right after the table (no punctual lights)";
    EXPECT_EQ(p.lightTreeDepth, 5u);
    EXPECT_EQ(p.lights.size(), p.lightCount + 3 * 63u);
    for (uint32_t e = 0; e < p.lightCount; ++e) {
        uint32_t triangle = uint32_t(p.lights[e].x);
        EXPECT_EQ(p.normals[triangle * layout::kNormalTexels].w, float(e));
        // Its leaf holds its power pmf, and its box holds the packed vertices.
        glm::vec4 lo = p.lights[p.lightTreeFirst + 3 * (31 + e)];
        EXPECT_EQ(lo.w, p.lights[e].z);
        glm::vec3 v0 = glm::vec3(p.triangles[triangle * layout::kTriangleTexels]);
        EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::vec3(lo), v0)));
    }
}

TEST(PackScene, BytesPerTriangleAreReported) {
    Scene s = randomScene(1000, 3);
    PackedScene p = packScene(s, buildFor(s));
    EXPECT_EQ(p.geometryBytes(), 16 * p.triangles.size() + 64 * size_t(p.nodeCount));
    EXPECT_GT(p.bytes(), p.geometryBytes());
}

TEST(PackScene, ChildLinksRoundTripAndRefuseWhatTheyCannotHold) {
    for (layout::ChildLink c :
         {layout::ChildLink{0, 0}, layout::ChildLink{12345, 0}, layout::ChildLink{0, 1},
          layout::ChildLink{layout::kMaxLeafFirst, layout::kMaxLeafCount}, layout::ChildLink{777, 3}}) {
        layout::ChildLink d = layout::decodeChild(layout::encodeChild(c));
        EXPECT_EQ(d.first, c.first);
        EXPECT_EQ(d.count, c.count);
    }
    EXPECT_THROW(layout::encodeChild({layout::kMaxLeafFirst + 1, 2}), Error);
    EXPECT_THROW(layout::encodeChild({0, layout::kMaxLeafCount + 1}), Error);
    // Coincident triangles cannot be split, so a builder allowed larger leaves makes one of all of them.
    Scene s = randomScene(1, 5);
    s.triangles.resize(layout::kMaxLeafCount + 1, s.triangles[0]);
    AabbArray bounds(s.triangles.size(), s.triangles[0].bounds());
    BvhBuildOptions wide;
    wide.maxLeafSize = int(layout::kMaxLeafCount) + 1;
    EXPECT_THROW(packScene(s, buildBinnedSah(bounds, wide)), Error);
}

// Two textures of different sizes on two of the three materials; every triangle's uv encodes its
// index, so the packed order can be checked against the BVH's.
Scene texturedScene(int triangles) {
    Scene s = randomScene(triangles, 5);
    for (int t = 0; t < 2; ++t) {
        Texture texture;
        texture.name = "t" + std::to_string(t);
        texture.image.width = 3 + t;
        texture.image.height = 2;
        for (int i = 0; i < texture.image.width * texture.image.height * 4; ++i)
            texture.image.texels.push_back(uint8_t(10 * t + i));
        s.textures.push_back(texture);
    }
    s.materials[0].diffuseTexture = 1;
    s.materials[2].diffuseTexture = 0;
    for (size_t i = 0; i < s.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) s.triangles[i].uv[size_t(k)] = glm::vec2(float(i), float(k));
    return s;
}

TEST(PackScene, TexcoordsInLeafOrderAndTheTextureTable) {
    Scene s = texturedScene(200);
    Bvh bvh = buildFor(s);
    PackedScene p = packScene(s, bvh);
    ASSERT_TRUE(p.hasTextures());
    ASSERT_EQ(p.texcoords.size(), 200u * layout::kTexcoordTexels);
    for (size_t i = 0; i < 200; ++i)
        for (int k = 0; k < 3; ++k)
            ASSERT_EQ(p.texcoords[i * layout::kTexcoordTexels + size_t(k)],
                      glm::vec2(float(bvh.primIndex[i]), float(k)));
    // The table: (first texel, width, height, 0), textures back to back.
    ASSERT_EQ(p.textureTable.size(), 2u);
    EXPECT_EQ(p.textureTable[0], glm::ivec4(0, 3, 2, 0));
    EXPECT_EQ(p.textureTable[1], glm::ivec4(6, 4, 2, 0));
    ASSERT_EQ(p.textureTexels.size(), 4u * (6 + 8));
    for (int t = 0; t < 2; ++t)
        for (size_t i = 0; i < s.textures[size_t(t)].image.texels.size(); ++i)
            EXPECT_EQ(p.textureTexels[4 * size_t(p.textureTable[size_t(t)].x) + i],
                      s.textures[size_t(t)].image.texels[i]);
    // Each material's maps texel names its texture first.
    for (size_t m = 0; m < 3; ++m)
        EXPECT_EQ(p.materials[m * layout::kMaterialTexels + layout::kMaterialMapsTexel].x,
                  float(s.materials[m].diffuseTexture))
            << m;
    EXPECT_EQ(p.textureBytes(), 8 * p.texcoords.size() + p.textureTexels.size() + 16 * 2);
    EXPECT_EQ(p.bytes(), packScene(randomScene(200, 5), bvh).bytes() + p.textureBytes());
}

TEST(PackScene, UntexturedScenesAllocateNoTextureData) {
    Scene s = texturedScene(20);
    for (Material& m : s.materials) m.diffuseTexture = -1;  // textures loaded but used by nobody
    PackedScene p = packScene(s, buildFor(s));
    EXPECT_FALSE(p.hasTextures());
    EXPECT_TRUE(p.texcoords.empty());
    EXPECT_TRUE(p.textureTexels.empty());
    EXPECT_EQ(p.textureBytes(), 0u);
}

// Every field of a material lands in the texel and channel layout.h documents, the triangles carry
// their material's alpha and single-sided flags, and the packed scene says which kinds of map and
// whether opacity tests are needed (the renderer's SURFACE_MAPS and SURFACE_OPACITY).
TEST(PackScene, MaterialTexelsFollowTheLayout) {
    Scene s = texturedScene(30);  // two textures, materials 0 and 2 textured by map_Kd
    Material& m = s.materials[2];
    m.type = MaterialType::MetallicRoughness;
    m.diffuse = glm::vec3(0.1f, 0.2f, 0.3f);
    m.emission = glm::vec3(4.0f, 5.0f, 6.0f);
    m.specular = glm::vec3(0.5f);  // not a metallic-roughness's: its slot holds specularColor
    m.specularColor = glm::vec3(0.7f, 0.8f, 0.9f);  // KHR_materials_specular
    m.absorption = glm::vec3(0.1f, 0.2f, 0.3f);     // KHR_materials_volume (read for glass only)
    m.clearcoat = 0.6f;                             // KHR_materials_clearcoat
    m.clearcoatRoughness = 0.2f;
    m.sheenColor = glm::vec3(0.25f, 0.5f, 0.75f);  // KHR_materials_sheen
    m.sheenRoughness = 0.4f;
    m.transmission = glm::vec3(0.4f);
    m.roughness = 0.25f;
    m.ior = 1.4f;
    m.metallic = 0.75f;
    m.alpha = 0.5f;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.3f;
    m.doubleSided = false;
    m.normalScale = 0.6f;
    m.metallicRoughnessTexture = 1;
    m.emissionTexture = 0;
    m.normalTexture = 1;
    m.alphaTexture = 0;
    m.specularTexture = 1;
    m.diffuseTexture = -1;
    PackedScene p = packScene(s, buildFor(s));
    ASSERT_EQ(p.materials.size(), 3u * layout::kMaterialTexels);
    const glm::vec4* t = &p.materials[2 * layout::kMaterialTexels];
    EXPECT_EQ(t[0], glm::vec4(0.1f, 0.2f, 0.3f, 4.0f));  // type 4: MetallicRoughness
    EXPECT_EQ(t[1], glm::vec4(4.0f, 5.0f, 6.0f, 0.25f));
    EXPECT_EQ(t[2], glm::vec4(0.7f, 0.8f, 0.9f, 1.4f));
    EXPECT_EQ(t[3], glm::vec4(0.4f, 0.4f, 0.4f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialMapsTexel], glm::vec4(-1.0f, 1.0f, 0.0f, 1.0f));
    EXPECT_EQ(t[layout::kMaterialAlphaTexel], glm::vec4(0.0f, 0.5f, 0.3f, 1.0f));  // mode 1: Mask
    EXPECT_EQ(t[layout::kMaterialExtraTexel], glm::vec4(0.75f, 0.6f, 1.0f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialVolumeTexel], glm::vec4(0.1f, 0.2f, 0.3f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialClearcoatTexel], glm::vec4(0.6f, 0.2f, 0.0f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialSheenTexel], glm::vec4(0.25f, 0.5f, 0.75f, 0.4f));
    EXPECT_EQ(p.surfaceMaps, layout::kDiffuseMapBit | layout::kRoughnessMapBit | layout::kEmissionMapBit |
                                 layout::kNormalMapBit | layout::kAlphaMapBit | layout::kSpecularMapBit);
    EXPECT_TRUE(p.opacity);
    Bvh bvh = buildFor(s);
    p = packScene(s, bvh);
    for (size_t i = 0; i < s.triangles.size(); ++i) {
        const float flags = p.triangles[i * layout::kTriangleTexels + 2].w;
        const bool third = s.triangles[bvh.primIndex[i]].material == 2;
        EXPECT_EQ(flags, third ? float(layout::kTriangleAlphaFlag + layout::kTriangleSingleSidedFlag) : 0.0f);
    }
    // Normal maps bring the tangents: three per triangle.
    EXPECT_EQ(p.tangents.size(), s.triangles.size() * layout::kTangentTexels);

    // Without the extras: no opacity, no tangents, and a plain material's extra texels are the defaults.
    m = Material{};
    p = packScene(s, buildFor(s));
    EXPECT_FALSE(p.opacity);
    EXPECT_EQ(p.surfaceMaps, layout::kDiffuseMapBit);
    EXPECT_TRUE(p.tangents.empty());
    t = &p.materials[2 * layout::kMaterialTexels];
    EXPECT_EQ(t[layout::kMaterialMapsTexel], glm::vec4(-1.0f));
    EXPECT_EQ(t[layout::kMaterialAlphaTexel], glm::vec4(-1.0f, 1.0f, 0.5f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialExtraTexel], glm::vec4(0.0f, 1.0f, -1.0f, 0.0f));
    EXPECT_EQ(t[layout::kMaterialVolumeTexel], glm::vec4(0.0f));
    EXPECT_EQ(t[layout::kMaterialClearcoatTexel], glm::vec4(0.0f));
    EXPECT_EQ(t[layout::kMaterialSheenTexel], glm::vec4(0.0f));
    for (size_t i = 0; i < s.triangles.size(); ++i)
        EXPECT_EQ(p.triangles[i * layout::kTriangleTexels + 2].w, 0.0f);
}

// A metallic-roughness material at its ends without maps that change that is packed as the model it
// equals (shaderMaterial), every other material as it is.
TEST(PackScene, MetallicRoughnessAtItsEndsIsPackedAsTheConductorOrThePlastic) {
    Material metal;
    metal.type = MaterialType::MetallicRoughness;
    metal.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);
    metal.metallic = 1.0f;
    metal.roughness = 0.3f;
    metal.normalTexture = 0;  // maps that do not change the model do not matter
    Material m = shaderMaterial(metal);
    EXPECT_EQ(m.type, MaterialType::Conductor);
    EXPECT_EQ(m.specular, metal.diffuse) << "F0 = the base colour";
    EXPECT_EQ(m.roughness, 0.3f);
    EXPECT_EQ(m.normalTexture, 0);
    Material dielectric = metal;
    dielectric.metallic = 0.0f;
    dielectric.diffuseTexture = 1;
    m = shaderMaterial(dielectric);
    EXPECT_EQ(m.type, MaterialType::Plastic);
    EXPECT_EQ(m.specular, glm::vec3(1.0f)) << "a white coat";
    dielectric.specularColor = glm::vec3(0.5f, 0.25f, 1.0f);  // KHR_materials_specular
    EXPECT_EQ(shaderMaterial(dielectric).specular, dielectric.specularColor) << "the coat tinted";
    EXPECT_EQ(m.diffuse, metal.diffuse);
    EXPECT_EQ(m.diffuseTexture, 1) << "the base colour map multiplies the plastic's Kd as it did the base";
    // Stays the blend: in between, a metallic-roughness map, a metal's base colour map.
    Material between = metal, mapped = metal, texturedMetal = metal;
    between.metallic = 0.5f;
    mapped.metallicRoughnessTexture = 2;
    texturedMetal.diffuseTexture = 1;
    Material coated = metal, sheened = metal;  // a clearcoat and a sheen are only the blend's
    coated.clearcoat = 0.5f;
    sheened.sheenColor = glm::vec3(0.5f);
    for (const Material& other : {between, mapped, texturedMetal, coated, sheened})
        EXPECT_EQ(shaderMaterial(other).type, MaterialType::MetallicRoughness);
    // And in the packed scene.
    Scene s = randomScene(10, 3);
    s.materials[0] = metal;
    s.materials[0].normalTexture = -1;
    PackedScene p = packScene(s, buildFor(s));
    EXPECT_EQ(p.materials[0], glm::vec4(metal.diffuse, float(MaterialType::Conductor)));
    EXPECT_EQ(p.materials[2], glm::vec4(metal.diffuse, 1.5f));  // Ks = F0, ior
}

// A triangle's tangent is dp/du in its plane and its sign says where dp/dv lies (Lengyel 2001): checked
// on a triangle whose uvs are a rotated, mirrored and scaled copy of its positions, where both
// derivatives are known exactly.
TEST(PackScene, TangentsFromPositionsAndUvs) {
    Triangle t;
    t.p = {glm::vec3(0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -3.0f)};
    t.n = {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    // u grows along +x (2 units per unit of u), v along -z: dp/du = (2, 0, 0), dp/dv = (0, 0, -3).
    t.uv = {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f)};
    glm::vec4 tangent = triangleTangent(t);
    EXPECT_NEAR(glm::distance(glm::vec3(tangent), glm::vec3(1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
    // cross(n, t) = (0, 1, 0) x (1, 0, 0) = (0, 0, -1): along dp/dv, so the sign is +1.
    EXPECT_EQ(tangent.w, 1.0f);
    // Mirror v: dp/dv = (0, 0, 3) now points against cross(n, t).
    t.uv = {glm::vec2(0.0f, 1.0f), glm::vec2(1.0f, 1.0f), glm::vec2(0.0f, 0.0f)};
    tangent = triangleTangent(t);
    EXPECT_NEAR(glm::distance(glm::vec3(tangent), glm::vec3(1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_EQ(tangent.w, -1.0f);
    // u along the triangle's second edge, rotated in the plane: dp/du = (0, 0, -3) / 1.
    t.uv = {glm::vec2(0.0f), glm::vec2(0.0f, 1.0f), glm::vec2(1.0f, 0.0f)};
    tangent = triangleTangent(t);
    EXPECT_NEAR(glm::distance(glm::vec3(tangent), glm::vec3(0.0f, 0.0f, -1.0f)), 0.0f, 1e-6f);
    // Degenerate uvs still give a unit tangent in the plane.
    t.uv = {glm::vec2(0.5f), glm::vec2(0.5f), glm::vec2(0.5f)};
    tangent = triangleTangent(t);
    EXPECT_NEAR(glm::length(glm::vec3(tangent)), 1.0f, 1e-6f);
    EXPECT_NEAR(tangent.y, 0.0f, 1e-6f);
}

// Tangents a loader gives (glTF's TANGENT) are packed as given, in leaf order; without them, or where a
// triple has a w of 0, each triangle's own is repeated at its three vertices.
TEST(PackScene, GivenTangentsArePackedInLeafOrder) {
    Scene s = texturedScene(40);
    s.materials[0].normalTexture = 0;
    Bvh bvh = buildFor(s);
    PackedScene p = packScene(s, bvh);
    ASSERT_EQ(p.tangents.size(), 40u * layout::kTangentTexels);
    for (size_t i = 0; i < 40; ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(p.tangents[i * 3 + size_t(k)], triangleTangent(s.triangles[bvh.primIndex[i]]));
    for (size_t i = 0; i < 40; ++i)
        s.tangents.push_back({glm::vec4(float(i), 0.0f, 0.0f, 1.0f), glm::vec4(0.0f, float(i), 0.0f, -1.0f),
                              glm::vec4(0.0f, 0.0f, float(i), 1.0f)});
    p = packScene(s, bvh);
    for (size_t i = 0; i < 40; ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(p.tangents[i * 3 + size_t(k)], s.tangents[bvh.primIndex[i]][size_t(k)]);
    // A triple with a w of 0 was not given (a glTF primitive without TANGENT): computed.
    s.tangents[7][1].w = 0.0f;
    p = packScene(s, bvh);
    for (size_t i = 0; i < 40; ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(p.tangents[i * 3 + size_t(k)], bvh.primIndex[i] == 7
                                                         ? triangleTangent(s.triangles[7])
                                                         : s.tangents[bvh.primIndex[i]][size_t(k)]);
    s.tangents.pop_back();
    EXPECT_THROW(packScene(s, bvh), Error);
}

TEST(PackScene, MismatchedBvhIsRejected) {
    Scene s = randomScene(10, 1);
    Scene other = randomScene(11, 1);
    EXPECT_THROW(packScene(s, buildFor(other)), Error);
}

// Punctual lights (pack/layout.h): their cdf entries follow the emitters' with index -1 - k and area 0,
// then kPunctualTexels each; the cdf still ends at 1, a black light gets no entry, and a scene without
// punctual lights packs exactly as before (the same texels). Caught: the cdf entry's index -k instead of
// -1 - k (light 0 would read as triangle 0).
TEST(PackScene, PunctualLightsFollowTheEmittersInTheCdf) {
    Scene s = randomScene(300, 7);
    const PackedScene before = packScene(s, buildFor(s));
    PunctualLight point, black, spot, sun;
    point.position = glm::vec3(1, 2, 3);
    point.intensity = glm::vec3(50.0f);
    black.intensity = glm::vec3(0.0f);
    spot.type = PunctualLightType::Spot;
    spot.position = glm::vec3(-1, 5, 0);
    spot.direction = glm::vec3(0, -1, 0);
    spot.intensity = glm::vec3(80, 40, 20);
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.6f;
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1, -1, 0));
    sun.intensity = glm::vec3(0.01f);
    s.punctualLights = {point, black, spot, sun};
    PackedScene p = packScene(s, buildFor(s));
    ASSERT_EQ(p.lightCount, 203u) << "200 emitters and 3 lights that emit";
    ASSERT_EQ(p.punctualCount, 3u);
    ASSERT_EQ(p.lights.size(), 203u + 3u * layout::kPunctualTexels);
    EXPECT_EQ(p.lights[202].y, 1.0f);
    const PunctualLight* expected[] = {&point, &spot, &sun};
    BoundingSphere sphere = directionalLightSphere(s);
    for (int k = 0; k < 3; ++k) {
        const glm::vec4 entry = p.lights[200 + size_t(k)];
        EXPECT_EQ(entry.x, -1.0f - float(k));
        EXPECT_EQ(entry.w, 0.0f);
        EXPECT_EQ(entry.y, p.lights[199 + size_t(k)].y + entry.z);
        const PunctualLight& l = *expected[k];
        float power = float(punctualLightPower(l, sphere.radius) / 3.14159265358979324);
        EXPECT_NEAR(entry.z, power / p.totalLightPower, 1e-5);
        const glm::vec4* data = &p.lights[203 + size_t(k) * layout::kPunctualTexels];
        EXPECT_EQ(data[0].w, float(l.type));
        EXPECT_EQ(glm::vec3(data[2]), l.intensity);
        if (l.type == PunctualLightType::Directional) {
            EXPECT_EQ(glm::vec3(data[0]), sphere.centre);
            EXPECT_EQ(data[1].w, sphere.radius);
            EXPECT_GT(sphere.radius, 10.0f) << "the random scene spans about 20";
        } else {
            EXPECT_EQ(glm::vec3(data[0]), l.position);
        }
        EXPECT_NEAR(glm::length(glm::vec3(data[1]) - l.direction), 0.0f, 1e-6f);
        if (l.type == PunctualLightType::Spot) {
            EXPECT_FLOAT_EQ(data[1].w, std::cos(0.6f));
            EXPECT_FLOAT_EQ(data[2].w, std::cos(0.2f));
        }
    }
    // The emitters share what the lights leave, in the same proportions as before.
    double emitterShare = double(p.lights[199].y);
    for (size_t i = 0; i < 200; ++i) EXPECT_NEAR(p.lights[i].z, before.lights[i].z * emitterShare, 2e-6) << i;

    // No punctual lights, no change: the same texels as a scene that never had the field.
    s.punctualLights.clear();
    PackedScene again = packScene(s, buildFor(s));
    EXPECT_EQ(again.punctualCount, 0u);
    ASSERT_EQ(again.lights.size(), before.lights.size());
    for (size_t i = 0; i < again.lights.size(); ++i) EXPECT_EQ(again.lights[i], before.lights[i]) << i;

    // A light the layout cannot render is refused, naming the scene.
    s.source = "scene.json";
    s.punctualLights = {spot};
    s.punctualLights[0].innerConeAngle = 0.7f;
    EXPECT_THROW(packScene(s, buildFor(s)), Error);
}

}  // namespace
}  // namespace fp

namespace fp {
namespace {

// The two-level layout (pack/layout.h): the top level's leaves link to instance node pairs holding the
// world-to-object and object-to-world rows and the root of the mesh's BVH; each mesh's triangles are
// stored once, after the world's, and only world triangles are emitters.
TEST(PackScene, InstancesGetATwoLevelBvhWithTheirMeshesStoredOnce) {
    Scene s = randomScene(30, 5);
    for (Triangle& t : s.triangles) t.material = 0;
    s.triangles[0].material = 1;  // one emitter, in the world
    Scene meshSource = randomScene(20, 6);
    s.meshes.push_back({"m", meshSource.triangles, {}});
    for (Triangle& t : s.meshes[0].triangles) t.material = 0;
    glm::mat4 a(1.0f), b(1.0f);
    a[3] = glm::vec4(5, 0, 0, 1);
    b[0][0] = 2.0f;
    b[3] = glm::vec4(0, -5, 1, 1);
    s.instances = {{0, a}, {0, b}};
    AabbArray meshBounds;
    for (const Triangle& t : s.meshes[0].triangles) meshBounds.push_back(t.bounds());
    std::vector<Bvh> meshBvhs = {buildBinnedSah(meshBounds)};
    PackedScene p = packScene(s, buildFor(s), meshBvhs);
    EXPECT_EQ(p.triangleCount, 50u) << "30 world triangles and the mesh's 20, once";
    EXPECT_EQ(p.instanceCount, 3u) << "two instances and the world";
    ASSERT_GT(p.instanceNodeStart, 0u);
    EXPECT_EQ(p.nodeCount, p.instanceNodeStart + 2 * p.instanceCount);
    // Only the world's emitter is in the light cdf.
    ASSERT_EQ(p.lightCount, 1u);
    EXPECT_LT(p.lights[0].x, 30.0f);
    // Each pair: world-to-object rows then the root; object-to-world rows. Entry order is the world's
    // (identity), then the instances'.
    auto rows = [&](uint32_t node) {
        glm::mat4 m(1.0f);
        for (int r = 0; r < 3; ++r) {
            glm::vec4 row = glm::uintBitsToFloat(p.nodes[size_t(node) * layout::kNodeTexels + size_t(r)]);
            for (int c = 0; c < 4; ++c) m[c][r] = row[c];
        }
        return m;
    };
    for (uint32_t k = 0; k < p.instanceCount; ++k) {
        uint32_t node = p.instanceNodeStart + 2 * k;
        glm::mat4 toWorld = k == 0 ? glm::mat4(1.0f) : s.instances[k - 1].objectToWorld;
        EXPECT_EQ(rows(node + 1), toWorld) << "entry " << k;
        glm::mat4 product = rows(node) * toWorld;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0f : 0.0f, 1e-6f);
        uint32_t root = p.nodes[size_t(node) * layout::kNodeTexels + 3].x;
        EXPECT_LT(root, p.instanceNodeStart);
        EXPECT_GT(root, 0u) << "node 0 is the top level's root";
        if (k == 2) {
            EXPECT_EQ(root, p.nodes[size_t(node - 2) * layout::kNodeTexels + 3].x) << "one mesh, one BVH";
        }
    }
    // Every leaf of the top level is a link to a pair (no triangle ranges at the top).
    int links = 0;
    for (int slot = 0; slot < 4; ++slot) {
        uint32_t link = p.nodes[layout::kNodeLinkTexel][slot];
        if (link == 0) continue;
        EXPECT_EQ(link & layout::kLeafBit, 0u);
        links += link >= p.instanceNodeStart;
    }
    EXPECT_EQ(links, 3) << "three entries fit in the root";
    // A mesh BVH for every mesh is required.
    EXPECT_THROW(packScene(s, buildFor(s)), Error);
}

}  // namespace
}  // namespace fp
