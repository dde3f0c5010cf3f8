#include "pack/pack.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bvh/wide_bvh.h"
#include "core/error.h"
#include "pack/layout.h"
#include "pack/light_tree.h"
#include "scene/instancing.h"
#include "scene/light_selection.h"
#include "scene/punctual_light.h"
#include "scene/spectrum.h"

namespace fp {

size_t PackedScene::bytes() const {
    return sizeof(glm::vec4) * (triangles.size() + normals.size() + materials.size() + lights.size()) +
           sizeof(glm::uvec4) * nodes.size() + textureBytes();
}

size_t PackedScene::textureBytes() const {
    return sizeof(glm::vec2) * texcoords.size() + textureTexels.size() +
           sizeof(glm::ivec4) * textureTable.size() + sizeof(glm::vec4) * (tangents.size() + colors.size());
}

std::array<glm::vec4, layout::kMaterialTexels> packMaterial(const Material& m) {
    auto index = [](int32_t t) { return float(std::max(t, -1)); };
    return {glm::vec4(m.diffuse, float(m.type)), glm::vec4(m.emission, m.roughness),
            // A metallic-roughness material has no Ks of its own: the slot holds its coat's tint.
            glm::vec4(m.type == MaterialType::MetallicRoughness ? m.specularColor : m.specular, m.ior),
            glm::vec4(m.transmission, spectrum::cauchyFromAbbe(m.ior, m.abbeNumber).y),
            glm::vec4(index(m.diffuseTexture), index(m.metallicRoughnessTexture), index(m.emissionTexture),
                      index(m.normalTexture)),
            glm::vec4(index(m.alphaTexture), m.alpha, m.alphaCutoff, float(m.alphaMode)),
            glm::vec4(m.metallic, m.normalScale, index(m.specularTexture), 0.0f),
            glm::vec4(m.absorption, 0.0f), glm::vec4(m.clearcoat, m.clearcoatRoughness, 0.0f, 0.0f),
            glm::vec4(m.sheenColor, m.sheenRoughness)};
}

bool hasVertexColors(const Scene& scene) {
    bool any = !scene.colors.empty();
    for (const InstancedMesh& mesh : scene.meshes) any = any || !mesh.colors.empty();
    return any;
}

Material shaderMaterial(const Material& m, bool vertexColors) {
    if (m.type != MaterialType::MetallicRoughness || m.metallicRoughnessTexture >= 0 || m.clearcoat > 0.0f ||
        m.sheenColor != glm::vec3(0.0f))
        return m;
    Material out = m;
    if (m.metallic >= 1.0f && m.diffuseTexture < 0 && !vertexColors) {
        out.type = MaterialType::Conductor;
        out.specular = m.diffuse;
        out.metallic = 0.0f;
    } else if (m.metallic <= 0.0f) {
        out.type = MaterialType::Plastic;
        out.specular = m.specularColor;
        out.metallic = 0.0f;
    }
    return out;
}

glm::vec4 triangleTangent(const Triangle& t) {
    const glm::vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const glm::vec2 d1 = t.uv[1] - t.uv[0], d2 = t.uv[2] - t.uv[0];
    glm::vec3 n = t.n[0] + t.n[1] + t.n[2];
    const glm::vec3 ng = glm::cross(e1, e2);
    n = glm::dot(n, n) > 1e-12f ? glm::normalize(n) : glm::normalize(ng);
    // Solve e1 = d1.x T + d1.y B, e2 = d2.x T + d2.y B for T = dp/du and B = dp/dv (Lengyel 2001).
    const float det = d1.x * d2.y - d2.x * d1.y;
    glm::vec3 tangent(0.0f), bitangent(0.0f);
    if (std::isfinite(det) && std::abs(det) > 0.0f) {
        tangent = (e1 * d2.y - e2 * d1.y) / det;
        bitangent = (e2 * d1.x - e1 * d2.x) / det;
    }
    tangent -= n * glm::dot(n, tangent);
    if (!(glm::dot(tangent, tangent) > 1e-30f) || !std::isfinite(glm::dot(tangent, tangent))) {
        // No usable uv gradient: any direction in the plane (the normal map is then meaningless anyway).
        tangent = e1 - n * glm::dot(n, e1);
        bitangent = glm::cross(n, tangent);
    }
    tangent = glm::normalize(tangent);
    float sign = glm::dot(glm::cross(n, tangent), bitangent) < 0.0f ? -1.0f : 1.0f;
    return glm::vec4(tangent, sign);
}

size_t PackedScene::geometryBytes() const {
    return sizeof(glm::vec4) * triangles.size() + sizeof(glm::uvec4) * nodes.size();
}

namespace {

// The sampling field of a texture's table entry (pack/layout.h).
int textureSampling(const Texture& t) {
    return int(t.wrapS) + (int(t.wrapT) << layout::kTextureWrapTShift) +
           (t.nearest ? layout::kTextureNearestFlag : 0) + (t.uvSlot == 1 ? layout::kTextureSlot1Flag : 0);
}

// Texture coordinates in leaf order (each triangle's slot 0, then with two slots its slot 1), and every
// texture's texels with its table entry (pack/layout.h); textures of the same texels share them.
void packTextures(const Scene& scene, const std::vector<const Triangle*>& ordered,
                  const std::vector<const std::array<glm::vec2, 3>*>& orderedTexcoords1, PackedScene* out) {
    for (const Texture& t : scene.textures) {
        if (t.uvSlot == 1) out->texcoordSlots = 2;
        out->textureSampling = out->textureSampling || (textureSampling(t) & ~layout::kTextureSlot1Flag) != 0;
    }
    out->texcoords.reserve(ordered.size() * layout::kTexcoordTexels * size_t(out->texcoordSlots));
    for (size_t i = 0; i < ordered.size(); ++i) {
        for (const glm::vec2& uv : ordered[i]->uv) out->texcoords.push_back(uv);
        if (out->texcoordSlots == 2)
            for (int k = 0; k < 3; ++k)
                out->texcoords.push_back(orderedTexcoords1[i] ? (*orderedTexcoords1[i])[size_t(k)]
                                                              : glm::vec2(0.0f));
    }
    // Which earlier texture holds the same texels (a glTF image read with two samplers or uv slots).
    auto sameTexels = [&scene](size_t k) {
        const Texture& t = scene.textures[k];
        for (size_t j = 0; j < k; ++j) {
            const Texture& u = scene.textures[j];
            if (u.name == t.name && u.image.width == t.image.width && u.image.height == t.image.height &&
                u.image.texels == t.image.texels)
                return j;
        }
        return k;
    };
    size_t texels = 0;
    for (const Texture& t : scene.textures) texels += size_t(t.image.width) * size_t(t.image.height);
    // The table holds offsets as signed 32-bit integers.
    if (texels >= (size_t(1) << 31))
        throw Error(scene.source + ": the textures have " + std::to_string(texels) +
                    " texels in all; the GPU layout addresses at most 2^31 - 1");
    out->textureTexels.reserve(texels * 4);
    for (size_t k = 0; k < scene.textures.size(); ++k) {
        const Texture& t = scene.textures[k];
        if (t.image.texels.size() != size_t(t.image.width) * size_t(t.image.height) * 4 || t.image.width <= 0)
            throw Error("internal: texture '" + t.name + "' has the wrong number of texels");
        size_t shared = sameTexels(k);
        int first = shared < k ? out->textureTable[shared].x : int(out->textureTexels.size() / 4);
        out->textureTable.emplace_back(first, t.image.width, t.image.height, textureSampling(t));
        if (shared == k)
            out->textureTexels.insert(out->textureTexels.end(), t.image.texels.begin(), t.image.texels.end());
    }
}

// A wide BVH's nodes quantised into out->nodes from node `nodeBase` on, its interior links moved by
// nodeBase and its leaves' triangle ranges by triangleBase (a mesh's BVH among others: pack/layout.h).
void appendNodes(WideBvh wide, uint32_t nodeBase, uint32_t triangleBase, PackedScene* out) {
    for (WideBvhNode& node : wide.nodes)
        for (int c = 0; c < node.childCount; ++c)
            node.first[c] += node.count[c] > 0 ? triangleBase : nodeBase;
    out->nodes.resize(size_t(nodeBase + wide.nodes.size()) * layout::kNodeTexels);
    for (size_t i = 0; i < wide.nodes.size(); ++i) {
        layout::QuantisedNode q = layout::quantiseNode(wide.nodes[i]);
        std::copy(q.begin(), q.end(), &out->nodes[(nodeBase + i) * layout::kNodeTexels]);
    }
}

// The rows of an affine transform's upper 3 x 4 as uint bits, then (root, 0, 0, 0): half of an instance's
// node pair (pack/layout.h).
void appendTransformNode(const glm::mat4& m, uint32_t root, PackedScene* out) {
    for (int r = 0; r < 3; ++r)
        out->nodes.push_back(glm::floatBitsToUint(glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r])));
    out->nodes.push_back(glm::uvec4(root, 0u, 0u, 0u));
}

// The two-level BVH of a scene with instances (pack/layout.h): the top level over the instances (and
// the world triangles as one more, untransformed), then the world triangles' BVH, each mesh's, and each
// instance's pair of transform nodes. Returns the most entries a traversal's stack can hold.
uint32_t packTwoLevel(const Scene& scene, const Bvh& bvh, const std::vector<Bvh>& meshBvhs,
                      const std::vector<uint32_t>& meshTriangleBase, PackedScene* out) {
    struct Entry {
        uint32_t bvh;  // 0: the world triangles' BVH; m + 1: mesh m's
        glm::mat4 objectToWorld;
    };
    std::vector<Entry> entries;
    AabbArray bounds;
    if (!scene.triangles.empty()) {
        entries.push_back({0, glm::mat4(1.0f)});
        bounds.push_back(bvh.nodes[0].bounds);
    }
    for (const Instance& instance : scene.instances) {
        entries.push_back({instance.mesh + 1, instance.objectToWorld});
        // The mesh's tree's root box is its bounds.
        bounds.push_back(instanceBounds(meshBvhs[instance.mesh].nodes[0].bounds, instance.objectToWorld));
    }
    BvhBuildOptions topOptions;
    topOptions.maxLeafSize = 1;  // each leaf is one instance, which its link names
    topOptions.threadCount = 1;
    Bvh top = buildBinnedSah(bounds, topOptions);
    WideBvh topWide = collapseToWide(top);
    std::vector<WideBvh> levels;
    levels.push_back(scene.triangles.empty() ? WideBvh{} : collapseToWide(bvh));
    for (const Bvh& mesh : meshBvhs) levels.push_back(collapseToWide(mesh));
    std::vector<uint32_t> root(levels.size());
    uint32_t next = uint32_t(topWide.nodes.size()), meshEntries = 0;
    for (size_t k = 0; k < levels.size(); ++k) {
        root[k] = next;
        next += uint32_t(levels[k].nodes.size());
        meshEntries = std::max(meshEntries, levels[k].stackEntries);
    }
    const uint32_t instanceNodes = next;
    // The top level's leaves become links to their instance's node pair.
    for (WideBvhNode& node : topWide.nodes)
        for (int c = 0; c < node.childCount; ++c)
            if (node.count[c] > 0) {
                node.first[c] = instanceNodes + 2 * top.primIndex[node.first[c]];
                node.count[c] = 0;
            }
    appendNodes(topWide, 0, 0, out);
    for (size_t k = 0; k < levels.size(); ++k)
        appendNodes(levels[k], root[k], k == 0 ? 0 : meshTriangleBase[k - 1], out);
    for (const Entry& e : entries) {
        appendTransformNode(glm::inverse(e.objectToWorld), root[e.bvh], out);
        appendTransformNode(e.objectToWorld, 0, out);
    }
    out->instanceCount = uint32_t(entries.size());
    out->instanceNodeStart = instanceNodes;
    out->nodeCount = uint32_t(out->nodes.size() / layout::kNodeTexels);
    // Every top-level child is a link to be visited (an instance is one), so up to three waiting siblings
    // a level down to the instance's node pair, which pushes none; then its mesh's own.
    return 3 * (topWide.depth + 1) + meshEntries;
}

}  // namespace

PackedScene packScene(const Scene& scene, const Bvh& bvh, const std::vector<Bvh>& meshBvhs) {
    PackedScene out;
    const size_t worldTriangles = bvh.primIndex.size();
    if (worldTriangles != scene.triangles.size() || (worldTriangles > 0 && bvh.nodes.empty()) ||
        meshBvhs.size() != (scene.instances.empty() ? 0 : scene.meshes.size()))
        throw Error("internal: BVH does not match the scene's " + std::to_string(scene.triangles.size()) +
                    " triangles");
    validateInstances(scene);
    // Every triangle stored, in leaf order: the world triangles', then each mesh's.
    std::vector<const Triangle*> ordered;
    std::vector<const std::array<glm::vec4, 3>*> orderedTangents, orderedColors;
    std::vector<const std::array<glm::vec2, 3>*> orderedTexcoords1;
    auto add = [&](const std::vector<Triangle>& triangles,
                   const std::vector<std::array<glm::vec4, 3>>& tangents,
                   const std::vector<std::array<glm::vec2, 3>>& texcoords1,
                   const std::vector<std::array<glm::vec4, 3>>& colors, const Bvh& tree) {
        for (size_t perTriangle : {tangents.size(), texcoords1.size(), colors.size()})
            if (perTriangle != 0 && perTriangle != triangles.size())
                throw Error("internal: " + std::to_string(perTriangle) + " vertex triples for " +
                            std::to_string(triangles.size()) + " triangles");
        for (uint32_t prim : tree.primIndex) {
            ordered.push_back(&triangles[prim]);
            orderedTangents.push_back(tangents.empty() ? nullptr : &tangents[prim]);
            orderedTexcoords1.push_back(texcoords1.empty() ? nullptr : &texcoords1[prim]);
            orderedColors.push_back(colors.empty() ? nullptr : &colors[prim]);
        }
    };
    add(scene.triangles, scene.tangents, scene.texcoords1, scene.colors, bvh);
    std::vector<uint32_t> meshTriangleBase;
    for (size_t m = 0; m < meshBvhs.size(); ++m) {
        if (meshBvhs[m].primIndex.size() != scene.meshes[m].triangles.size())
            throw Error("internal: BVH does not match instanced mesh " + std::to_string(m));
        meshTriangleBase.push_back(uint32_t(ordered.size()));
        const InstancedMesh& mesh = scene.meshes[m];
        add(mesh.triangles, mesh.tangents, mesh.texcoords1, mesh.colors, meshBvhs[m]);
    }
    const size_t n = ordered.size();
    if (n == 0) throw Error("internal: a scene without triangles");
    if (n >= layout::kMaxFloatIndex || scene.materials.size() >= layout::kMaxFloatIndex)
        throw Error(scene.source + ": " + std::to_string(n) + " triangles and " +
                    std::to_string(scene.materials.size()) + " materials; the GPU layout addresses at most " +
                    std::to_string(layout::kMaxFloatIndex - 1) + " of each");
    out.triangleCount = uint32_t(n);

    // Emitters and their selection probabilities, proportional to emitted power (luminance * area).
    // (Emitters are world triangles: instancing.h.)
    EmitterPmfs emitters = emitterPmfs(scene, bvh.primIndex.data(), bvh.primIndex.size());
    out.totalLightPower = float(emitters.totalPower);
    std::vector<float> pmf = emitters.pmf;
    pmf.resize(n, 0.0f);

    bool textured = false;
    const bool vertexColors = hasVertexColors(scene);
    std::vector<float> triangleFlags(scene.materials.size(), 0.0f);
    for (size_t k = 0; k < scene.materials.size(); ++k) {
        const Material& m = scene.materials[k];
        const int32_t maps[] = {m.diffuseTexture,  m.metallicRoughnessTexture,
                                m.emissionTexture, m.normalTexture,
                                m.alphaTexture,    m.specularTexture};
        const int bits[] = {layout::kDiffuseMapBit, layout::kRoughnessMapBit, layout::kEmissionMapBit,
                            layout::kNormalMapBit,  layout::kAlphaMapBit,     layout::kSpecularMapBit};
        for (int j = 0; j < 6; ++j) {
            if (maps[j] >= int32_t(scene.textures.size()))
                throw Error("internal: material '" + m.name + "' names texture " + std::to_string(maps[j]) +
                            " of " + std::to_string(scene.textures.size()));
            if (maps[j] >= 0) out.surfaceMaps |= bits[j];
        }
        textured = textured || m.hasTextures();
        triangleFlags[k] = float((m.hasAlpha() ? layout::kTriangleAlphaFlag : 0) +
                                 (m.doubleSided ? 0 : layout::kTriangleSingleSidedFlag));
        out.opacity = out.opacity || m.needsOpacityTest();
        for (const glm::vec4& texel : packMaterial(shaderMaterial(m, vertexColors)))
            out.materials.push_back(texel);
    }
    const bool tangents = (out.surfaceMaps & layout::kNormalMapBit) != 0;
    // A normal map's own uv slot gives its computed tangents (pack.h, triangleTangent).
    std::vector<int> normalSlot(scene.materials.size(), 0);
    for (size_t k = 0; k < scene.materials.size(); ++k)
        if (scene.materials[k].normalTexture >= 0)
            normalSlot[k] = scene.textures[size_t(scene.materials[k].normalTexture)].uvSlot;

    out.triangles.reserve(n * layout::kTriangleTexels);
    out.normals.reserve(n * layout::kNormalTexels);
    if (tangents) out.tangents.reserve(n * layout::kTangentTexels);
    if (vertexColors) out.colors.reserve(n * layout::kColorTexels);
    float cdf = 0.0f;
    std::vector<LightTreeEmitter> treeEmitters;  // the emitter entries, for the light tree
    for (size_t i = 0; i < n; ++i) {
        const Triangle& t = *ordered[i];
        out.triangles.emplace_back(t.p[0], float(t.material));
        out.triangles.emplace_back(t.p[1] - t.p[0], pmf[i]);
        out.triangles.emplace_back(t.p[2] - t.p[0], triangleFlags[t.material]);
        if (tangents) {
            const std::array<glm::vec4, 3>* given = orderedTangents[i];
            if (!given || (*given)[0].w == 0.0f || (*given)[1].w == 0.0f || (*given)[2].w == 0.0f) {
                Triangle inSlot = t;
                if (normalSlot[t.material] == 1 && orderedTexcoords1[i]) inSlot.uv = *orderedTexcoords1[i];
                glm::vec4 tangent = triangleTangent(inSlot);
                for (int v = 0; v < 3; ++v) out.tangents.push_back(tangent);
            } else {
                for (const glm::vec4& tangent : *given) out.tangents.push_back(tangent);
            }
        }
        if (vertexColors)
            for (int v = 0; v < 3; ++v)
                out.colors.push_back(orderedColors[i] ? (*orderedColors[i])[size_t(v)] : glm::vec4(1.0f));
        const float entry = pmf[i] > 0.0f ? float(out.lights.size()) : 0.0f;  // its light-table entry
        for (int v = 0; v < 3; ++v) out.normals.emplace_back(t.n[v], v == 0 ? entry : 0.0f);
        if (pmf[i] > 0.0f) {
            cdf += pmf[i];  // exact: every pmf and partial sum is a multiple of 2^-24 in [0, 1]
            out.lights.emplace_back(float(i), cdf, pmf[i], 0.0f);
            treeEmitters.push_back({t.p[0], t.p[1], t.p[2], pmf[i]});
        }
    }
    // Punctual lights: their cdf entries after the triangles', then their data (pack/layout.h). One with
    // no power (black) has no entry and is never sampled, as a black emitter triangle has none.
    std::vector<uint32_t> punctual;
    for (size_t k = 0; k < scene.punctualLights.size(); ++k) {
        validatePunctualLight(scene.punctualLights[k], scene.source + ": light " + std::to_string(k));
        float p = emitters.punctualPmf[k];
        if (!(p > 0.0f)) continue;
        cdf += p;
        out.lights.emplace_back(-1.0f - float(punctual.size()), cdf, p, 0.0f);
        punctual.push_back(uint32_t(k));
    }
    out.lightCount = uint32_t(out.lights.size());
    out.punctualCount = uint32_t(punctual.size());
    if (!punctual.empty()) {
        BoundingSphere sphere = directionalLightSphere(scene);
        for (uint32_t k : punctual) {
            const PunctualLight& l = scene.punctualLights[k];
            glm::vec3 position = l.position;
            float a = 0.0f, b = 0.0f;
            if (l.type == PunctualLightType::Spot) {
                a = std::cos(l.outerConeAngle);
                b = std::cos(l.innerConeAngle);
            } else if (l.type == PunctualLightType::Directional) {
                position = sphere.centre;
                a = sphere.radius;
            }
            out.lights.emplace_back(position, float(l.type));
            out.lights.emplace_back(glm::normalize(l.direction), a);
            out.lights.emplace_back(l.intensity, b);
        }
    }
    // The light tree (pack/light_tree.h) after them, in scenes without punctual lights (which it does
    // not bound) and of at most layout::kMaxLightTreeEmitters emitters.
    if (punctual.empty() && !treeEmitters.empty() && treeEmitters.size() <= layout::kMaxLightTreeEmitters) {
        LightTree tree = buildLightTree(treeEmitters);
        out.lightTreeFirst = uint32_t(out.lights.size());
        out.lightTreeDepth = uint32_t(tree.depth);
        for (const glm::vec4& texel : lightTreeTexels(tree)) out.lights.push_back(texel);
    }

    if (textured) packTextures(scene, ordered, orderedTexcoords1, &out);

    if (scene.instances.empty()) {
        WideBvh wide = collapseToWide(bvh);
        out.stackEntries = wide.stackEntries;
        appendNodes(std::move(wide), 0, 0, &out);
        out.nodeCount = uint32_t(out.nodes.size() / layout::kNodeTexels);
    } else {
        out.stackEntries = packTwoLevel(scene, bvh, meshBvhs, meshTriangleBase, &out);
    }
    return out;
}

}  // namespace fp
