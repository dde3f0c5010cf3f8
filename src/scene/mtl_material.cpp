// MTL statements -> fragpath's material types; the rules are documented in mtl.h.
#include <algorithm>
#include <cmath>

#include "scene/mtl.h"

namespace fp {

namespace {

// Sanitized colours have no negative or NaN channels, so "not black" means some channel is positive.
bool isBlack(const glm::vec3& c) {
    return !(c.x > 0.0f || c.y > 0.0f || c.z > 0.0f);
}

// The MTL spec's illumination models with transparency: 4 (glass, ray-traced reflection), 6 and 7
// (refraction, without and with Fresnel) and 9 (glass without ray-traced reflection).
bool isTransparentModel(int illum) {
    return illum == 4 || illum == 6 || illum == 7 || illum == 9;
}

// Models 0 (colour, no ambient) and 1 (colour and ambient) are the spec's ones without a Ks term.
bool isSpecularOff(int illum) {
    return illum == 0 || illum == 1;
}

}  // namespace

float roughnessFromPhong(float ns) {
    // Walter et al. 2007, eq. 33 solved for the width: alpha = sqrt(2 / (Ns + 2)). Our roughness is
    // sqrt(alpha) because the shader squares it (GGX alpha = roughness^2).
    float alpha = std::sqrt(2.0f / (std::max(ns, 0.0f) + 2.0f));
    return std::sqrt(alpha);
}

Material materialFromMtl(const MtlMaterial& mtl) {
    Material m;
    m.name = mtl.name;
    m.diffuse = mtl.kd;
    m.emission = mtl.ke;
    // With map_Pr alone the texture is the roughness (a factor of 1), as map_Kd alone is the colour.
    auto roughness = [&](float otherwise) { return mtl.pr ? *mtl.pr : mtl.roughnessMap ? 1.0f : otherwise; };

    // An explicit illum names the lighting model and wins over Tf; see rule 1 in mtl.h.
    bool glass = mtl.illum ? isTransparentModel(*mtl.illum) : !isBlack(mtl.tf);
    if (glass) {
        m.type = MaterialType::Dielectric;
        m.ior = mtl.ni.value_or(1.5f);
        m.transmission = isBlack(mtl.tf) ? glm::vec3(1.0f) : mtl.tf;
        m.roughness = roughness(0.0f);
        m.abbeNumber = mtl.vd.value_or(0.0f);
    } else if (mtl.pm || mtl.metallicMap) {
        m.type = MaterialType::MetallicRoughness;
        m.metallic = mtl.pm.value_or(1.0f);
        m.roughness = roughness(0.5f);
        // As the plastic's coat (rule 4): "Ni 1" means nothing on an opaque material.
        m.ior = mtl.ni && *mtl.ni > 1.0f ? *mtl.ni : 1.5f;
    } else if (mtl.illum == 5 && !isBlack(mtl.ks)) {
        m.type = MaterialType::Conductor;
        m.specular = mtl.ks;
        m.roughness = roughness(0.0f);
    } else if (!isBlack(mtl.ks) && !(mtl.illum && isSpecularOff(*mtl.illum))) {
        m.type = MaterialType::Plastic;
        m.specular = mtl.ks;
        // Exporters write "Ni 1" on opaque materials, where it means nothing; a coat of index 1 would
        // reflect nothing, so a coat takes the common 1.5 unless the file gives a real index.
        m.ior = mtl.ni && *mtl.ni > 1.0f ? *mtl.ni : 1.5f;
        m.roughness = mtl.pr             ? *mtl.pr
                      : mtl.roughnessMap ? 1.0f
                      : mtl.ns           ? roughnessFromPhong(*mtl.ns)
                                         : 0.5f;
    }
    // Coverage: a dissolve below 1, or a map of it, makes the material a BLEND one (stochastic opacity).
    m.alpha = mtl.d.value_or(1.0f);
    if (m.alpha < 1.0f || mtl.alphaMap) m.alphaMode = AlphaMode::Blend;
    return m;
}

}  // namespace fp
