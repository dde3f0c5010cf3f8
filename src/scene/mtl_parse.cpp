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

std::vector<Material> parseMtl(std::string_view text, const std::string& name,
                               std::vector<MtlTexture>* textures) {
    std::vector<MtlGiven> given;
    std::istringstream stream(sanitizeMtl(text, name, &given));
    std::map<std::string, int> index;
    std::vector<tinyobj::material_t> parsed;
    std::string tinyWarnings, tinyErrors;  // only about statements we do not use (d/Tr, texture options)
    tinyobj::LoadMtl(&index, &parsed, &stream, &tinyWarnings, &tinyErrors);

    std::vector<Material> materials;
    materials.reserve(parsed.size());
    RepairTally unusedMaps;
    size_t named = 0;
    for (const tinyobj::material_t& m : parsed) {
        // tinyobjloader always flushes its last material, even when no newmtl ever named one.
        if (m.name.empty()) continue;
        // The sanitizer saw the same named newmtl statements, so the entries match one to one; the
        // check only guards against a tinyobjloader that splits materials differently.
        MtlGiven has = named < given.size() ? given[named] : MtlGiven{};
        ++named;
        MtlMaterial mtl;
        mtl.name = m.name;
        // Without Kd: 0 (a pure emitter is often written that way), or with map_Kd 1 (the texture alone).
        mtl.kd = has.kd ? color(m.diffuse) : glm::vec3(has.diffuseMap.empty() ? 0.0f : 1.0f);
        mtl.ke = color(m.emission);
        mtl.ks = color(m.specular);
        mtl.tf = color(m.transmittance);  // Tf or Kt
        if (has.illum) mtl.illum = m.illum;
        if (has.ni) mtl.ni = m.ior;
        if (has.ns) mtl.ns = m.shininess;
        if (has.pr) mtl.pr = m.roughness;
        if (has.pm) mtl.pm = m.metallic;
        // tinyobjloader keeps statements it does not know, such as our Vd, as text.
        if (has.vd) {
            auto it = m.unknown_parameter.find("Vd");
            if (it != m.unknown_parameter.end()) mtl.vd = std::stof(it->second);
        }
        Material material = materialFromMtl(mtl);
        if (!has.diffuseMap.empty()) {
            if (material.type == MaterialType::Diffuse || material.type == MaterialType::Plastic) {
                material.diffuseTexture = static_cast<int32_t>(textures->size());
                textures->push_back({has.diffuseMap, has.diffuseMapLine});
            } else {
                unusedMaps.add(has.diffuseMapLine);
            }
        }
        materials.push_back(material);
    }
    unusedMaps.report(name, "ignored map_Kd of", "metal or glass material",
                      "(only Lambertian and plastic materials have a diffuse colour)");
    if (materials.empty()) warn(name + ": defines no materials (no newmtl statement)");
    return materials;
}

}  // namespace fp
