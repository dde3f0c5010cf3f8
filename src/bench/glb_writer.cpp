#include "bench/glb_writer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace fp::bench {

namespace {

using json = nlohmann::json;

// A vertex as the bytes of its position and normal, for sharing equal ones.
struct VertexKey {
    float v[6];
    bool operator==(const VertexKey& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
};
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = 1469598103934665603ull;  // FNV-1a over the bytes
        const unsigned char* bytes = reinterpret_cast<const unsigned char*>(k.v);
        for (size_t i = 0; i < sizeof k.v; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
        return size_t(h);
    }
};

void append(std::string* bin, const void* data, size_t bytes) {
    bin->append(static_cast<const char*>(data), bytes);
    bin->append((4 - bin->size() % 4) % 4, '\0');  // glTF aligns views to their component size
}

json materialJson(const Material& m) {
    json pbr = {{"baseColorFactor", {m.diffuse.r, m.diffuse.g, m.diffuse.b, 1.0}},
                {"metallicFactor", 0.0},
                {"roughnessFactor", 1.0}};
    json out = {{"name", m.name}, {"pbrMetallicRoughness", pbr}, {"doubleSided", true}};
    float strength = std::max({m.emission.r, m.emission.g, m.emission.b});
    if (strength > 0.0f) {
        glm::vec3 factor = strength > 1.0f ? m.emission / strength : m.emission;
        out["emissiveFactor"] = {factor.r, factor.g, factor.b};
        if (strength > 1.0f)
            out["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}};
    }
    return out;
}

}  // namespace

void writeGlb(const Scene& scene, const std::string& path) {
    std::map<uint32_t, std::vector<size_t>> byMaterial;
    for (size_t i = 0; i < scene.triangles.size(); ++i) byMaterial[scene.triangles[i].material].push_back(i);

    json doc = {{"asset", {{"version", "2.0"}, {"generator", "fragpath bench"}}}};
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    std::string bin;
    json primitives = json::array();
    for (const auto& [material, triangles] : byMaterial) {
        std::unordered_map<VertexKey, uint32_t, VertexKeyHash> index;
        std::vector<float> positions, normals;
        std::vector<uint32_t> indices;
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (size_t t : triangles)
            for (int c = 0; c < 3; ++c) {
                const glm::vec3 &p = scene.triangles[t].p[c], &n = scene.triangles[t].n[c];
                VertexKey key{{p.x, p.y, p.z, n.x, n.y, n.z}};
                auto [it, added] = index.emplace(key, uint32_t(positions.size() / 3));
                if (added) {
                    positions.insert(positions.end(), {p.x, p.y, p.z});
                    normals.insert(normals.end(), {n.x, n.y, n.z});
                    lo = glm::min(lo, p);
                    hi = glm::max(hi, p);
                }
                indices.push_back(it->second);
            }
        auto accessor = [&](const void* data, size_t bytes, int componentType, size_t count,
                            const char* type) {
            doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}});
            append(&bin, data, bytes);
            doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                                        {"componentType", componentType},
                                        {"count", count},
                                        {"type", type}});
            return doc["accessors"].size() - 1;
        };
        size_t vertices = positions.size() / 3;
        size_t p = accessor(positions.data(), positions.size() * 4, 5126, vertices, "VEC3");
        doc["accessors"][p]["min"] = {lo.x, lo.y, lo.z};
        doc["accessors"][p]["max"] = {hi.x, hi.y, hi.z};
        size_t n = accessor(normals.data(), normals.size() * 4, 5126, vertices, "VEC3");
        size_t i = accessor(indices.data(), indices.size() * 4, 5125, indices.size(), "SCALAR");
        doc["materials"].push_back(materialJson(scene.materials[material]));
        primitives.push_back({{"attributes", {{"POSITION", p}, {"NORMAL", n}}},
                              {"indices", i},
                              {"material", doc["materials"].size() - 1}});
    }
    doc["meshes"] = {{{"primitives", primitives}}};
    doc["nodes"] = {{{"mesh", 0}}};
    doc["scenes"] = {{{"nodes", {0}}}};
    doc["scene"] = 0;
    doc["buffers"] = {{{"byteLength", bin.size()}}};

    // The GLB container (glTF 2.0, section 4.4): a 12-byte header, then the JSON chunk padded with
    // spaces and the BIN chunk padded with zeros, each to 4 bytes.
    std::string text = doc.dump();
    text.append((4 - text.size() % 4) % 4, ' ');
    auto word = [](std::string* out, uint32_t v) { out->append(reinterpret_cast<const char*>(&v), 4); };
    std::string file;
    word(&file, 0x46546C67u);  // "glTF"
    word(&file, 2u);
    word(&file, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    word(&file, uint32_t(text.size()));
    word(&file, 0x4E4F534Au);  // "JSON"
    file += text;
    word(&file, uint32_t(bin.size()));
    word(&file, 0x004E4942u);  // "BIN"
    file += bin;
    std::ofstream out(path, std::ios::binary);
    out.write(file.data(), std::streamsize(file.size()));
    if (!out.good()) throw Error("cannot write " + path);
}

}  // namespace fp::bench
