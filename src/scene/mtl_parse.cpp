#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "core/log.h"
#include "scene/mtl.h"
#include "scene/repair_tally.h"

namespace fp {

namespace {

glm::vec3 color(const tinyobj::real_t c[3]) {
    return glm::vec3(c[0], c[1], c[2]);
}

}  // namespace

const char* mtlMapName(MtlMap map) {
    static const char* const kNames[kMtlMapCount] = {"map_Kd", "map_Ks", "map_Ke", "map_Pr",
                                                     "map_Pm", "map_d",  "norm",   "map_Bump"};
    int i = int(map);
    return i >= 0 && i < kMtlMapCount ? kNames[i] : "map";
}

std::vector<Material> parseMtl(std::string_view text, const std::string& name,
                               std::vector<MtlTexture>* textures) {
    std::vector<MtlGiven> given;
    std::istringstream stream(sanitizeMtl(text, name, &given));
    std::map<std::string, int> index;
    std::vector<tinyobj::material_t> parsed;
    std::string tinyWarnings, tinyErrors;  // only about statements we do not use (Tr, texture options)
    tinyobj::LoadMtl(&index, &parsed, &stream, &tinyWarnings, &tinyErrors);

    std::vector<Material> materials;
    materials.reserve(parsed.size());
    // Maps on types that do not use them, one tally per statement.
    RepairTally unusedMaps[kMtlMapCount];
    size_t named = 0;
    for (const tinyobj::material_t& m : parsed) {
        // tinyobjloader always flushes its last material, even when no newmtl ever named one.
        if (m.name.empty()) continue;
        // The sanitizer saw the same named newmtl statements, so the entries match one to one; the
        // check only guards against a tinyobjloader that splits materials differently.
        MtlGiven has = named < given.size() ? given[named] : MtlGiven{};
        ++named;
        auto hasMap = [&has](MtlMap map) { return !has.map(map).file.empty(); };
        MtlMaterial mtl;
        mtl.name = m.name;
        // Without Kd: 0 (a pure emitter is often written that way), or with map_Kd 1 (the texture alone);
        // the same for Ke with map_Ke and Ks with map_Ks.
        mtl.kd = has.kd ? color(m.diffuse) : glm::vec3(hasMap(MtlMap::Kd) ? 1.0f : 0.0f);
        mtl.ke = has.ke ? color(m.emission) : glm::vec3(hasMap(MtlMap::Ke) ? 1.0f : 0.0f);
        mtl.ks = has.ks ? color(m.specular) : glm::vec3(hasMap(MtlMap::Ks) ? 1.0f : 0.0f);
        mtl.tf = color(m.transmittance);  // Tf or Kt
        if (has.illum) mtl.illum = m.illum;
        if (has.ni) mtl.ni = m.ior;
        if (has.ns) mtl.ns = m.shininess;
        if (has.pr) mtl.pr = m.roughness;
        if (has.pm) mtl.pm = m.metallic;
        if (has.d) mtl.d = m.dissolve;  // not from Tr, which tinyobjloader also reads into it
        // tinyobjloader keeps statements it does not know, such as our Vd, as text.
        if (has.vd) {
            auto it = m.unknown_parameter.find("Vd");
            if (it != m.unknown_parameter.end()) mtl.vd = std::stof(it->second);
        }
        mtl.roughnessMap = hasMap(MtlMap::Pr);
        mtl.metallicMap = hasMap(MtlMap::Pm);
        mtl.alphaMap = hasMap(MtlMap::D);
        Material material = materialFromMtl(mtl);
        const MaterialType type = material.type;

        auto add = [&](MtlTexture texture) {
            textures->push_back(std::move(texture));
            return static_cast<int32_t>(textures->size() - 1);
        };
        auto color = [&](MtlMap map) {
            const MtlMapStatement& s = has.map(map);
            MtlTexture t;
            t.file = s.file;
            t.line = s.line;
            t.statement = mtlMapName(map);
            return add(t);
        };
        // Each map where its type uses it; elsewhere a warning (below) names the statement.
        auto use = [&](MtlMap map, bool used) {
            if (!hasMap(map)) return false;
            if (!used) unusedMaps[int(map)].add(has.map(map).line);
            return used;
        };
        const bool hasDiffuse = type == MaterialType::Diffuse || type == MaterialType::Plastic ||
                                type == MaterialType::MetallicRoughness;
        const bool hasSpecular = type == MaterialType::Conductor || type == MaterialType::Plastic;
        if (use(MtlMap::Kd, hasDiffuse)) material.diffuseTexture = color(MtlMap::Kd);
        if (use(MtlMap::Ks, hasSpecular)) material.specularTexture = color(MtlMap::Ks);
        if (use(MtlMap::Ke, true)) material.emissionTexture = color(MtlMap::Ke);
        const bool roughness = use(MtlMap::Pr, type != MaterialType::Diffuse);
        const bool metallic = use(MtlMap::Pm, type == MaterialType::MetallicRoughness);
        if (roughness || metallic) {
            MtlTexture t;
            t.kind = MtlTextureKind::MetallicRoughness;
            t.statement = roughness ? "map_Pr" : "map_Pm";
            if (roughness) {
                t.file = has.map(MtlMap::Pr).file;
                t.line = has.map(MtlMap::Pr).line;
                t.channel = has.map(MtlMap::Pr).channel;
            }
            if (metallic) {
                t.metallicFile = has.map(MtlMap::Pm).file;
                t.metallicLine = has.map(MtlMap::Pm).line;
                t.metallicChannel = has.map(MtlMap::Pm).channel;
            }
            material.metallicRoughnessTexture = add(t);
        }
        if (use(MtlMap::D, true)) {
            MtlTexture t;
            t.kind = MtlTextureKind::Alpha;
            t.file = has.map(MtlMap::D).file;
            t.line = has.map(MtlMap::D).line;
            t.statement = "map_d";
            t.channel = has.map(MtlMap::D).channel;
            material.alphaTexture = add(t);
        }
        // norm wins over map_Bump / bump.
        MtlMap normal = hasMap(MtlMap::Norm) ? MtlMap::Norm : MtlMap::Bump;
        if (use(normal, true)) {
            MtlTexture t;
            t.kind = MtlTextureKind::Normal;
            t.file = has.map(normal).file;
            t.line = has.map(normal).line;
            t.statement = mtlMapName(normal);
            material.normalTexture = add(t);
            material.normalScale = has.map(normal).bumpScale;
        }
        materials.push_back(material);
    }
    unusedMaps[int(MtlMap::Kd)].report(name, "ignored map_Kd of", "metal or glass material",
                                       "(only Lambertian, plastic and metallic-roughness materials have a "
                                       "diffuse colour)");
    unusedMaps[int(MtlMap::Ks)].report(name, "ignored map_Ks of", "material",
                                       "(only plastics and illum 5 metals have a Ks)");
    unusedMaps[int(MtlMap::Pr)].report(name, "ignored map_Pr of", "Lambertian material", "(no roughness)");
    unusedMaps[int(MtlMap::Pm)].report(name, "ignored map_Pm of", "glass material",
                                       "(glass is not metallic)");
    if (materials.empty()) warn(name + ": defines no materials (no newmtl statement)");
    return materials;
}

}  // namespace fp
