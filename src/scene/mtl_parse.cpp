#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "core/log.h"
#include "scene/mtl.h"

namespace fp {

std::vector<Material> parseMtl(std::string_view text, const std::string& name) {
    std::istringstream stream(sanitizeMtl(text, name));
    std::map<std::string, int> index;
    std::vector<tinyobj::material_t> parsed;
    std::string tinyWarnings, tinyErrors;  // only about statements we do not use (d/Tr, texture options)
    tinyobj::LoadMtl(&index, &parsed, &stream, &tinyWarnings, &tinyErrors);

    std::vector<Material> materials;
    materials.reserve(parsed.size());
    for (const tinyobj::material_t& m : parsed) {
        // tinyobjloader always flushes its last material, even when no newmtl ever named one.
        if (m.name.empty()) continue;
        Material material;
        material.name = m.name;
        // A material without Kd keeps tinyobjloader's 0 (a pure emitter is often written that way).
        material.diffuse = glm::vec3(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
        material.emission = glm::vec3(m.emission[0], m.emission[1], m.emission[2]);
        materials.push_back(material);
    }
    if (materials.empty()) warn(name + ": defines no materials (no newmtl statement)");
    return materials;
}

}  // namespace fp
