// Surface scattering. Directions are in the local shading frame (the normal is +z) and wo, the
// direction back toward where the path came from, always has wo.z > 0: the frame is built on the
// side the ray arrived from (surface.glsl). Every function returns f(wo, wi) |cos(theta_i)|, the
// form the estimators multiply by, and densities are per unit solid angle of wi.
//
// Models (the types of fp::MaterialType, src/scene/scene.h):
//   diffuse     Lambertian, f = Kd / pi
//   conductor   GGX microfacets (Trowbridge & Reitz 1975; Walter et al. 2007) with Smith masking and
//               Schlick's Fresnel from F0 = Ks; visible-normal sampling (Heitz 2018)
//   plastic     a GGX dielectric coat (exact Fresnel, ior) over a Lambertian base Kd
//   dielectric  glass: exact Fresnel reflection and refraction, smooth or GGX-rough (Walter et al. 2007)
//   metallic-roughness  glTF 2.0's model (glTF 2.0 specification, Appendix B): the linear blend
//               metallic * conductor(F0 = base colour) + (1 - metallic) * plastic(white coat of index
//               ior over a Lambertian base colour), both lobes with the same GGX roughness; the
//               coat's reflectance tinted by Ks, which holds glTF's KHR_materials_specular colour;
//               optionally under a sheen (KHR_materials_sheen) and a clearcoat (KHR_materials_
//               clearcoat): a Charlie sheen lobe and a second GGX lobe on top
//   unlit       glTF's KHR_materials_unlit: no scattering; the base colour is radiance the surface
//               shows (surface.glsl, emittedRadiance)
// Roughness below kSmooth makes a lobe a perfect mirror or refractor: a "delta" lobe that only
// sampling can find, so light sampling skips it and MIS gives its hits full weight.
#include "common/luminance.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"

#define MATERIAL_DIFFUSE 0
#define MATERIAL_CONDUCTOR 1
#define MATERIAL_PLASTIC 2
#define MATERIAL_DIELECTRIC 3
#define MATERIAL_METALLIC_ROUGHNESS 4
#define MATERIAL_UNLIT 5
const float kSmooth = 0.01;

// MATERIAL_TYPES is a bit mask of the types present in the scene (bit = fp::MaterialType), injected by
// the renderer, so that a scene of Lambertian surfaces compiles none of the other models' code.
#ifndef MATERIAL_TYPES
#define MATERIAL_TYPES 63
#endif
#define HAS_TYPE(t) ((MATERIAL_TYPES & (1 << t)) != 0)
// MATERIAL_CLEARCOAT: 1 when some metallic-roughness material has a clearcoat (the renderer's choice);
// the tests' probe, which leaves it out, compiles it.
#ifndef MATERIAL_CLEARCOAT
#define MATERIAL_CLEARCOAT 1
#endif
#define HAS_CLEARCOAT (MATERIAL_CLEARCOAT != 0 && HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS))
#ifndef MATERIAL_SHEEN
#define MATERIAL_SHEEN 1
#endif
#define HAS_SHEEN (MATERIAL_SHEEN != 0 && HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS))

struct MaterialData {
    int type;
    vec3 diffuse, emission, specular, transmission;  // diffuse: a metallic-roughness's base colour
    float roughness, ior;
    float cauchyB;  // nm^2; > 0 for a dispersive glass, whose ior is the index at 587.6 nm
    float metallic;  // metallic-roughness only (0 for the other types)
    float clearcoat, clearcoatRoughness;  // metallic-roughness only, with HAS_CLEARCOAT (else 0)
    vec3 sheenColor;                      // metallic-roughness only, with HAS_SHEEN (else 0)
    float sheenRoughness;
};

MaterialData fetchMaterial(int m) {
    vec4 a = materialTexel(m * MATERIAL_TEXELS);
    vec4 b = materialTexel(m * MATERIAL_TEXELS + 1);
    vec4 c = materialTexel(m * MATERIAL_TEXELS + 2);
    vec4 d = materialTexel(m * MATERIAL_TEXELS + 3);
    float metallic = 0.0;
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    metallic = materialTexel(m * MATERIAL_TEXELS + MATERIAL_EXTRA_TEXEL).x;
#endif
    vec2 clearcoat = vec2(0.0);
#if HAS_CLEARCOAT
    if (int(a.w) == MATERIAL_METALLIC_ROUGHNESS) clearcoat = materialTexel(m * MATERIAL_TEXELS + MATERIAL_CLEARCOAT_TEXEL).xy;
#endif
    vec4 sheen = vec4(0.0);
#if HAS_SHEEN
    if (int(a.w) == MATERIAL_METALLIC_ROUGHNESS) sheen = materialTexel(m * MATERIAL_TEXELS + MATERIAL_SHEEN_TEXEL);
#endif
    return MaterialData(int(a.w), a.rgb, b.rgb, c.rgb, d.rgb, b.w, c.w, d.w, metallic, clearcoat.x, clearcoat.y, sheen.rgb, sheen.w);
}

bool isDeltaOnly(MaterialData m) {
#if MATERIAL_TYPES == 1
    return false;
#endif
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    if (m.type == MATERIAL_METALLIC_ROUGHNESS)
        return m.metallic >= 1.0 && m.roughness < kSmooth && (m.clearcoat <= 0.0 || m.clearcoatRoughness < kSmooth) &&
               m.sheenColor == vec3(0.0);
#endif
#if HAS_TYPE(MATERIAL_UNLIT)
    if (m.type == MATERIAL_UNLIT) return true;  // no lobe at all: nothing for a light sample to find
#endif
    return (m.type == MATERIAL_CONDUCTOR || m.type == MATERIAL_DIELECTRIC) && m.roughness < kSmooth;
}

struct BsdfSample {
    vec3 wi;      // local frame
    vec3 weight;  // f |cos(theta_i)| / pdf
    float pdf;    // solid-angle density (for MIS); 0 for a delta lobe
    bool delta;
};

// A glossy caster (src/pack/caustic_casters.h, which sets GLOSSY_CASTER_ROUGHNESS): a metal whose one
// lobe is nearly smooth. The light its highlight throws on other surfaces is a caustic, which nee's light
// pass traces (integrators/nee.glsl) as it does the light of a delta lobe.
#ifndef GLOSSY_CASTER_ROUGHNESS
#error "GLOSSY_CASTER_ROUGHNESS is set by the layout defines (src/gpu/layout_defines.cpp)"
#endif
bool isGlossyCaster(MaterialData m) {
    bool metal = m.type == MATERIAL_CONDUCTOR;
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    metal = metal || (m.type == MATERIAL_METALLIC_ROUGHNESS && m.metallic >= 1.0);
#endif
    return metal && m.roughness < GLOSSY_CASTER_ROUGHNESS;
}

// Whether the lobe a BSDF sample took is a caustic caster's: a delta lobe, or a glossy caster's.
bool casterLobe(BsdfSample bs, MaterialData m) { return bs.delta || isGlossyCaster(m); }

// ---- Fresnel ----
// Unpolarised Fresnel reflectance of a dielectric interface (pbrt-v4 eq. 9.5). cosI > 0 on the incident
// side; eta = n_transmitted / n_incident. Total internal reflection gives 1.
float fresnelDielectric(float cosI, float eta) {
    float sin2T = (1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return 1.0;
    float cosT = sqrt(1.0 - sin2T);
    float parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
    float perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (parallel * parallel + perpendicular * perpendicular);
}

// Schlick 1994: reflectance of a conductor from its reflectance at normal incidence.
vec3 fresnelSchlick(vec3 f0, float cosI) {
    float m = clamp(1.0 - cosI, 0.0, 1.0);
    return f0 + (1.0 - f0) * (m * m * m * m * m);
}

// ---- GGX (Trowbridge-Reitz) microfacets, isotropic, alpha = roughness^2 ----
float ggxAlpha(float roughness) { return max(roughness * roughness, 1e-4); }

// Normal distribution D(wm) (pbrt-v4 eq. 9.16, isotropic).
float ggxD(vec3 wm, float alpha) {
    float a2 = alpha * alpha;
    // cos^2 (a2 - 1) + 1 written as sin^2 + cos^2 a2 (wm is unit): the usual form cancels
    // catastrophically near the peak of a narrow lobe, where cos^2 is close to 1.
    float d = (wm.x * wm.x + wm.y * wm.y) + wm.z * wm.z * a2;
    return a2 / (PI * d * d);
}

// Smith's auxiliary function Lambda(w) (pbrt-v4 eq. 9.22).
float ggxLambda(vec3 w, float alpha) {
    float cos2 = w.z * w.z;
    float tan2 = max(0.0, 1.0 - cos2) / max(cos2, 1e-12);
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

float ggxG1(vec3 w, float alpha) { return 1.0 / (1.0 + ggxLambda(w, alpha)); }
// Height-correlated masking-shadowing (pbrt-v4 eq. 9.27).
float ggxG(vec3 wo, vec3 wi, float alpha) { return 1.0 / (1.0 + ggxLambda(wo, alpha) + ggxLambda(wi, alpha)); }

// Density of visible normals D_wo(wm) = G1(wo) max(0, wo.wm) D(wm) / cos(theta_o) (Heitz 2018, eq. 3).
float ggxVisiblePdf(vec3 wo, vec3 wm, float alpha) {
    return ggxG1(wo, alpha) * max(0.0, dot(wo, wm)) * ggxD(wm, alpha) / abs(wo.z);
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4): stretch, sample the
// projected hemisphere, unstretch. Requires wo.z > 0.
vec3 ggxSampleVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float lensq = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x), phi = 2.0 * PI * u.y;
    float p1 = r * cos(phi), p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(alpha * nh.x, alpha * nh.y, max(1e-6, nh.z)));
}

vec3 reflectLocal(vec3 wo, vec3 wm) { return -wo + 2.0 * dot(wo, wm) * wm; }

// ---- conductor ----
vec3 conductorEval(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0 || m.roughness < kSmooth) return vec3(0.0);
    float alpha = ggxAlpha(m.roughness);
    vec3 wm = normalize(wo + wi);
    vec3 F = fresnelSchlick(m.specular, dot(wo, wm));
    return ggxD(wm, alpha) * ggxG(wo, wi, alpha) * F / (4.0 * wo.z);  // f cos(theta_i)
}

float conductorPdf(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0 || m.roughness < kSmooth) return 0.0;
    vec3 wm = normalize(wo + wi);
    return ggxVisiblePdf(wo, wm, ggxAlpha(m.roughness)) / (4.0 * dot(wo, wm));
}

bool conductorSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
    if (m.roughness < kSmooth) {
        s = BsdfSample(vec3(-wo.x, -wo.y, wo.z), fresnelSchlick(m.specular, wo.z), 0.0, true);
        return true;
    }
    vec3 wm = ggxSampleVisibleNormal(wo, ggxAlpha(m.roughness), u.xy);
    vec3 wi = reflectLocal(wo, wm);
    if (wi.z <= 0.0) return false;
    float pdf = conductorPdf(m, wo, wi);
    s = BsdfSample(wi, pdf > 0.0 ? conductorEval(m, wo, wi) / pdf : vec3(0.0), pdf, false);
    return pdf > 0.0;
}

// ---- plastic: GGX dielectric coat over Lambertian ----
// The base is seen through the coat twice, attenuated by (1 - F) on the way in and out. The lobe to
// sample is chosen in proportion to the reflectance each lobe shows at wo.
float plasticSpecularProbability(MaterialData m, vec3 wo) {
    float coat = fresnelDielectric(wo.z, m.ior) * luminance(m.specular);
    float base = (1.0 - fresnelDielectric(wo.z, m.ior)) * luminance(m.diffuse);
    return coat + base > 0.0 ? clamp(coat / (coat + base), 0.05, 0.95) : 0.5;
}

vec3 plasticEval(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0) return vec3(0.0);
    vec3 f = m.diffuse / PI * (1.0 - fresnelDielectric(wo.z, m.ior)) * (1.0 - fresnelDielectric(wi.z, m.ior)) * wi.z;
    if (m.roughness >= kSmooth) {
        float alpha = ggxAlpha(m.roughness);
        vec3 wm = normalize(wo + wi);
        f += m.specular * ggxD(wm, alpha) * ggxG(wo, wi, alpha) * fresnelDielectric(dot(wo, wm), m.ior) / (4.0 * wo.z);
    }
    return f;
}

float plasticPdf(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0) return 0.0;
    float p = plasticSpecularProbability(m, wo);
    float pdf = (1.0 - p) * wi.z / PI;
    if (m.roughness >= kSmooth) {
        vec3 wm = normalize(wo + wi);
        pdf += p * ggxVisiblePdf(wo, wm, ggxAlpha(m.roughness)) / (4.0 * dot(wo, wm));
    }
    return pdf;
}

bool plasticSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
    float p = plasticSpecularProbability(m, wo);
    if (u.z < p && m.roughness < kSmooth) {
        vec3 weight = m.specular * fresnelDielectric(wo.z, m.ior) / p;
        s = BsdfSample(vec3(-wo.x, -wo.y, wo.z), weight, 0.0, true);
        return true;
    }
    vec3 wi;
    if (u.z < p) {
        wi = reflectLocal(wo, ggxSampleVisibleNormal(wo, ggxAlpha(m.roughness), u.xy));
    } else {
        wi = sampleCosineLocal(u.xy);
    }
    if (wi.z <= 0.0) return false;
    float pdf = plasticPdf(m, wo, wi);
    // A smooth coat's delta lobe was not chosen: the diffuse part carries the whole non-delta weight.
    s = BsdfSample(wi, pdf > 0.0 ? plasticEval(m, wo, wi) / pdf : vec3(0.0), pdf, false);
    return pdf > 0.0;
}

// ---- dielectric ----
// eta = n_transmitted / n_incident as seen from wo's side: ior when entering (front face), 1/ior leaving.
// Radiance is scaled by 1/eta^2 on refraction (pbrt-v4 section 9.5.2), since paths start at the camera.
vec3 dielectricEval(MaterialData m, vec3 wo, vec3 wi, float eta) {
    if (m.roughness < kSmooth || wi.z == 0.0) return vec3(0.0);
    float alpha = ggxAlpha(m.roughness);
    bool reflect = wi.z > 0.0;
    vec3 wm = reflect ? wo + wi : wi * eta + wo;  // generalised half vector (Walter et al. 2007, eq. 16)
    if (dot(wm, wm) == 0.0) return vec3(0.0);
    wm = normalize(wm);
    if (wm.z < 0.0) wm = -wm;
    if (dot(wm, wi) * wi.z < 0.0 || dot(wm, wo) < 0.0) return vec3(0.0);  // backfacing microfacets
    float F = fresnelDielectric(dot(wo, wm), eta);
    float D = ggxD(wm, alpha), G = ggxG(wo, wi, alpha);
    if (reflect) return vec3(D * G * F / (4.0 * wo.z));
    float denom = dot(wi, wm) + dot(wo, wm) / eta;
    // Walter et al. 2007, eq. 21, times |cos(theta_i)|, and the 1/eta^2 radiance scaling.
    float ft = D * G * (1.0 - F) * abs(dot(wi, wm) * dot(wo, wm) / (wo.z * denom * denom)) / (eta * eta);
    return m.transmission * ft;
}

float dielectricPdf(MaterialData m, vec3 wo, vec3 wi, float eta) {
    if (m.roughness < kSmooth || wi.z == 0.0) return 0.0;
    float alpha = ggxAlpha(m.roughness);
    bool reflect = wi.z > 0.0;
    vec3 wm = reflect ? wo + wi : wi * eta + wo;
    if (dot(wm, wm) == 0.0) return 0.0;
    wm = normalize(wm);
    if (wm.z < 0.0) wm = -wm;
    if (dot(wm, wi) * wi.z < 0.0 || dot(wm, wo) < 0.0) return 0.0;
    float F = fresnelDielectric(dot(wo, wm), eta);
    float pdfWm = ggxVisiblePdf(wo, wm, alpha);
    if (reflect) return pdfWm / (4.0 * dot(wo, wm)) * F;
    float denom = dot(wi, wm) + dot(wo, wm) / eta;
    return pdfWm * abs(dot(wi, wm)) / (denom * denom) * (1.0 - F);  // Jacobian of refraction, eq. 17
}

bool dielectricSample(MaterialData m, vec3 wo, vec3 u, float eta, out BsdfSample s) {
    if (m.roughness < kSmooth) {
        float F = fresnelDielectric(wo.z, eta);
        if (u.z < F) {
            s = BsdfSample(vec3(-wo.x, -wo.y, wo.z), vec3(1.0), 0.0, true);
            return true;
        }
        vec3 wi = refract(-wo, vec3(0.0, 0.0, 1.0), 1.0 / eta);
        if (wi == vec3(0.0)) return false;  // cannot happen: F = 1 under total internal reflection
        s = BsdfSample(wi, m.transmission / (eta * eta), 0.0, true);
        return true;
    }
    vec3 wm = ggxSampleVisibleNormal(wo, ggxAlpha(m.roughness), u.xy);
    float F = fresnelDielectric(dot(wo, wm), eta);
    vec3 wi = u.z < F ? reflectLocal(wo, wm) : refract(-wo, wm, 1.0 / eta);
    if (u.z < F ? wi.z <= 0.0 : (wi.z >= 0.0 || wi == vec3(0.0))) return false;
    float pdf = dielectricPdf(m, wo, wi, eta);
    s = BsdfSample(wi, pdf > 0.0 ? dielectricEval(m, wo, wi, eta) / pdf : vec3(0.0), pdf, false);
    return pdf > 0.0;
}

// ---- metallic-roughness: glTF 2.0's BRDF (specification, Appendix B) ----
// f = metallic f_conductor + (1 - metallic) f_plastic, where f_conductor is the conductor above with
// F0 = base colour (Schlick's Fresnel, as glTF's conductor_fresnel) and f_plastic the plastic above with
// a coat of index ior (1.5: glTF's dielectric F0 = 0.04), its reflectance tinted by Ks (the specularColor
// of KHR_materials_specular, white without it), over a Lambertian base colour (glTF's
// fresnel_mix of the diffuse and specular lobes, with exact Fresnel and the base seen through the coat
// on the way in and out, as in our plastic). Both lobes have GGX alpha = roughness^2. Sampling picks the
// conductor with probability metallic and then samples it as the conductor does (else the plastic, with
// its own choice of coat or base); a non-delta direction then gets the mixture's value and density,
// metallic pdf_conductor + (1 - metallic) pdf_plastic (the one-sample model of Veach 1997, section 9.2.4,
// which keeps MIS correct); a delta direction (a smooth lobe) keeps the weight its model gave it, since
// the lobe's share of f and its probability of being chosen are the same factor. metallic 0 and 1 are
// exactly the plastic and the conductor (the same functions, no blend). The plastic is m itself: its Ks
// is the coat's tint (pack.cpp packs specularColor there).
MaterialData metallicRoughnessConductor(MaterialData m) {
    m.specular = m.diffuse;
    return m;
}

vec3 metallicRoughnessEval(MaterialData m, vec3 wo, vec3 wi) {
    if (m.metallic >= 1.0) return conductorEval(metallicRoughnessConductor(m), wo, wi);
    if (m.metallic <= 0.0) return plasticEval(m, wo, wi);
    return m.metallic * conductorEval(metallicRoughnessConductor(m), wo, wi) +
           (1.0 - m.metallic) * plasticEval(m, wo, wi);
}

float metallicRoughnessPdf(MaterialData m, vec3 wo, vec3 wi) {
    if (m.metallic >= 1.0) return conductorPdf(metallicRoughnessConductor(m), wo, wi);
    if (m.metallic <= 0.0) return plasticPdf(m, wo, wi);
    return m.metallic * conductorPdf(metallicRoughnessConductor(m), wo, wi) +
           (1.0 - m.metallic) * plasticPdf(m, wo, wi);
}

bool metallicRoughnessSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
    if (m.metallic >= 1.0) return conductorSample(metallicRoughnessConductor(m), wo, u, s);
    if (m.metallic <= 0.0) return plasticSample(m, wo, u, s);
    // u.z picks the lobe and, rescaled to the chosen share, is the plastic's own lobe choice.
    bool found;
    if (u.z < m.metallic) {
        found = conductorSample(metallicRoughnessConductor(m), wo, u, s);
    } else {
        float v = min((u.z - m.metallic) / (1.0 - m.metallic), 0.99999994);
        found = plasticSample(m, wo, vec3(u.xy, v), s);
    }
    if (!found || s.delta) return found;
    s.pdf = metallicRoughnessPdf(m, wo, s.wi);
    s.weight = s.pdf > 0.0 ? metallicRoughnessEval(m, wo, s.wi) / s.pdf : vec3(0.0);
    return s.pdf > 0.0;
}

// ---- sheen: KHR_materials_sheen over the metallic-roughness model ----
// A sheen lobe of colour C and roughness r (clamped to [0.1, 1]; a = r^2): the Charlie distribution of
// Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF", D(h) = (2 + 1/a) sin(theta_h)^(1/a)
// / (2 pi), with the visibility term of Neubelt & Pettineo 2013, V = 1 / (4 (cos_i + cos_o - cos_i cos_o)),
// the pair KHR_materials_sheen describes. Its white directional albedo E(mu, r) is kSheenAlbedo (made by
// tools/sheen_albedo.py); E exceeds 1 at grazing angles for small r, so the lobe is divided by
// max(1, E(cos_o), E(cos_i)) (symmetric: reciprocal; its albedo is then at most min(1, E) = E'). Layered
// as the specification's albedo scaling, in the product form the clearcoat uses:
//   f = C D V / max(1, E_o, E_i) + (1 - s E'(cos_o)) (1 - s E'(cos_i)) f_base,   s = max(C),
// so the albedo is at most s E' + (1 - s E') = 1. Sampling: cosine-weighted for the sheen, chosen in
// proportion to s E'(cos_o) against the base colour's luminance (clamped to [0.05, 0.95]).
const float kSheenAlbedo[256] = float[256](
    3.8914, 1.3917, 0.5820, 0.2377, 0.0912, 0.0321, 0.0101, 0.0028, 0.0006, 0.0001, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000,
    2.4860, 1.2519, 0.7224, 0.4214, 0.2423, 0.1354, 0.0727, 0.0371, 0.0178, 0.0078, 0.0031, 0.0011, 0.0003, 0.0001, 0.0000, 0.0000,
    1.8470, 1.0943, 0.7289, 0.4943, 0.3345, 0.2236, 0.1466, 0.0936, 0.0577, 0.0339, 0.0188, 0.0096, 0.0044, 0.0017, 0.0004, 0.0000,
    1.4859, 0.9685, 0.7001, 0.5161, 0.3816, 0.2806, 0.2040, 0.1459, 0.1021, 0.0693, 0.0453, 0.0281, 0.0161, 0.0082, 0.0034, 0.0007,
    1.2567, 0.8719, 0.6644, 0.5165, 0.4037, 0.3148, 0.2439, 0.1869, 0.1410, 0.1042, 0.0749, 0.0519, 0.0341, 0.0206, 0.0108, 0.0039,
    1.1000, 0.7973, 0.6303, 0.5083, 0.4126, 0.3349, 0.2708, 0.2172, 0.1723, 0.1346, 0.1030, 0.0767, 0.0548, 0.0370, 0.0225, 0.0112,
    0.9874, 0.7390, 0.6001, 0.4970, 0.4146, 0.3464, 0.2887, 0.2393, 0.1967, 0.1598, 0.1278, 0.1000, 0.0759, 0.0552, 0.0374, 0.0223,
    0.9035, 0.6929, 0.5742, 0.4852, 0.4132, 0.3527, 0.3007, 0.2554, 0.2156, 0.1803, 0.1489, 0.1209, 0.0959, 0.0736, 0.0537, 0.0361,
    0.8392, 0.6558, 0.5521, 0.4739, 0.4100, 0.3558, 0.3088, 0.2673, 0.2302, 0.1969, 0.1667, 0.1392, 0.1142, 0.0913, 0.0704, 0.0512,
    0.7888, 0.6257, 0.5334, 0.4635, 0.4062, 0.3572, 0.3143, 0.2761, 0.2416, 0.2103, 0.1815, 0.1550, 0.1305, 0.1077, 0.0865, 0.0666,
    0.7486, 0.6010, 0.5176, 0.4543, 0.4021, 0.3574, 0.3180, 0.2827, 0.2507, 0.2212, 0.1940, 0.1687, 0.1449, 0.1226, 0.1016, 0.0816,
    0.7160, 0.5806, 0.5041, 0.4461, 0.3982, 0.3570, 0.3206, 0.2878, 0.2579, 0.2302, 0.2045, 0.1804, 0.1576, 0.1360, 0.1154, 0.0958,
    0.6892, 0.5634, 0.4926, 0.4389, 0.3945, 0.3562, 0.3224, 0.2917, 0.2637, 0.2377, 0.2134, 0.1905, 0.1687, 0.1480, 0.1280, 0.1088,
    0.6670, 0.5490, 0.4828, 0.4326, 0.3911, 0.3553, 0.3236, 0.2949, 0.2685, 0.2439, 0.2209, 0.1992, 0.1784, 0.1585, 0.1394, 0.1208,
    0.6483, 0.5367, 0.4743, 0.4270, 0.3880, 0.3543, 0.3244, 0.2973, 0.2724, 0.2492, 0.2274, 0.2067, 0.1869, 0.1679, 0.1495, 0.1316,
    0.6325, 0.5262, 0.4670, 0.4221, 0.3852, 0.3533, 0.3250, 0.2993, 0.2757, 0.2537, 0.2330, 0.2133, 0.1944, 0.1762, 0.1586, 0.1414);

float sheenRoughness(MaterialData m) { return clamp(m.sheenRoughness, 0.1, 1.0); }

// kSheenAlbedo at (mu, r), bilinear.
float sheenAlbedo(float mu, float r) {
    vec2 x = vec2(clamp(mu, 0.0, 1.0), (r - 0.1) / 0.9) * 15.0;
    ivec2 i = min(ivec2(x), ivec2(14));
    vec2 f = x - vec2(i);
    int k = i.y * 16 + i.x;
    return mix(mix(kSheenAlbedo[k], kSheenAlbedo[k + 1], f.x), mix(kSheenAlbedo[k + 16], kSheenAlbedo[k + 17], f.x), f.y);
}

float sheenStrength(MaterialData m) { return max(m.sheenColor.r, max(m.sheenColor.g, m.sheenColor.b)); }

// s E'(mu): what the sheen takes from the base along a direction of cosine mu.
float sheenShare(MaterialData m, float mu) { return sheenStrength(m) * min(1.0, sheenAlbedo(abs(mu), sheenRoughness(m))); }

float sheenProbability(MaterialData m, vec3 wo) {
    float sheen = sheenShare(m, wo.z);
    float base = (1.0 - sheen) * max(luminance(m.diffuse), 0.04);
    return clamp(sheen / (sheen + base), 0.05, 0.95);
}

vec3 sheenedEval(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0) return vec3(0.0);
    float r = sheenRoughness(m), a = r * r;
    vec3 h = normalize(wo + wi);
    float D = (2.0 + 1.0 / a) * pow(max(0.0, 1.0 - h.z * h.z), 0.5 / a) / (2.0 * PI);
    float V = 1.0 / (4.0 * (wi.z + wo.z - wi.z * wo.z));
    float norm = max(1.0, max(sheenAlbedo(wo.z, r), sheenAlbedo(wi.z, r)));
    float base = (1.0 - sheenShare(m, wo.z)) * (1.0 - sheenShare(m, wi.z));
    return m.sheenColor * (D * V * wi.z / norm) + base * metallicRoughnessEval(m, wo, wi);
}

float sheenedPdf(MaterialData m, vec3 wo, vec3 wi) {
    if (wi.z <= 0.0) return 0.0;
    float p = sheenProbability(m, wo);
    return p * wi.z / PI + (1.0 - p) * metallicRoughnessPdf(m, wo, wi);
}

bool sheenedSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
    float p = sheenProbability(m, wo);
    vec3 wi;
    if (u.z < p) {
        s = BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
        wi = sampleCosineLocal(u.xy);
    } else {
        float v = min((u.z - p) / (1.0 - p), 0.99999994);
        if (!metallicRoughnessSample(m, wo, vec3(u.xy, v), s)) return false;
        if (s.delta) {
            s.weight *= (1.0 - sheenShare(m, wo.z)) * (1.0 - sheenShare(m, s.wi.z)) / (1.0 - p);
            return true;
        }
        wi = s.wi;
    }
    if (wi.z <= 0.0) return false;
    float pdf = sheenedPdf(m, wo, wi);
    s = BsdfSample(wi, pdf > 0.0 ? sheenedEval(m, wo, wi) / pdf : vec3(0.0), pdf, false);
    return pdf > 0.0;
}

// The metallic-roughness model with its sheen, if it has one: what a clearcoat lies on.
vec3 sheenLayerEval(MaterialData m, vec3 wo, vec3 wi) {
#if HAS_SHEEN
    if (m.sheenColor != vec3(0.0)) return sheenedEval(m, wo, wi);
#endif
    return metallicRoughnessEval(m, wo, wi);
}

float sheenLayerPdf(MaterialData m, vec3 wo, vec3 wi) {
#if HAS_SHEEN
    if (m.sheenColor != vec3(0.0)) return sheenedPdf(m, wo, wi);
#endif
    return metallicRoughnessPdf(m, wo, wi);
}

bool sheenLayerSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
#if HAS_SHEEN
    if (m.sheenColor != vec3(0.0)) return sheenedSample(m, wo, u, s);
#endif
    return metallicRoughnessSample(m, wo, u, s);
}

// ---- clearcoat: KHR_materials_clearcoat over the metallic-roughness model (and its sheen) ----
// A clear dielectric coat of index 1.5 (the extension's fixed F0 = 0.04) and its own GGX roughness on
// top, weighted by the clearcoat factor c and layered as our plastic layers its coat over its base (and
// as the extension's specification layers it, with the Fresnel term taken at the macro-surface normal):
//   f = c f_coat(wo, wi) + (1 - c F(cos_o)) (1 - c F(cos_i)) f_base(wo, wi),
// f_coat = D G F(wo.h) / (4 cos_o cos_i). What the coat reflects at wo is taken from what reaches the base,
// on the way in and out, so f is reciprocal and its albedo at most 1 (tests/render/
// gltf_material_extensions_test.cpp). Sampling picks the coat with probability cF / (cF + (1 - cF) b),
// b the base colour's luminance (what the base roughly reflects), clamped to [0.05, 0.95]; a non-delta
// direction gets the mixture's density, a delta one (a smooth coat, or a smooth lobe of the base) its
// lobe's weight over the probability of choosing it.
const float kClearcoatIor = 1.5;

float clearcoatFresnel(MaterialData m, float cosTheta) { return m.clearcoat * fresnelDielectric(abs(cosTheta), kClearcoatIor); }

float clearcoatProbability(MaterialData m, vec3 wo) {
    float coat = clearcoatFresnel(m, wo.z);
    float base = (1.0 - coat) * max(luminance(m.diffuse), 0.04);
    return clamp(coat / (coat + base), 0.05, 0.95);
}

// What the coat lets through to the base and back: (1 - c F(cos_o)) (1 - c F(cos_i)).
float clearcoatTransmittance(MaterialData m, vec3 wo, vec3 wi) {
    return (1.0 - clearcoatFresnel(m, wo.z)) * (1.0 - clearcoatFresnel(m, wi.z));
}

vec3 clearcoatedEval(MaterialData m, vec3 wo, vec3 wi) {
    vec3 f = clearcoatTransmittance(m, wo, wi) * sheenLayerEval(m, wo, wi);
    if (wi.z > 0.0 && m.clearcoatRoughness >= kSmooth) {
        float alpha = ggxAlpha(m.clearcoatRoughness);
        vec3 wm = normalize(wo + wi);
        f += vec3(m.clearcoat * ggxD(wm, alpha) * ggxG(wo, wi, alpha) * fresnelDielectric(dot(wo, wm), kClearcoatIor) / (4.0 * wo.z));
    }
    return f;
}

float clearcoatedPdf(MaterialData m, vec3 wo, vec3 wi) {
    float p = clearcoatProbability(m, wo);
    float pdf = (1.0 - p) * sheenLayerPdf(m, wo, wi);
    if (wi.z > 0.0 && m.clearcoatRoughness >= kSmooth) {
        vec3 wm = normalize(wo + wi);
        pdf += p * ggxVisiblePdf(wo, wm, ggxAlpha(m.clearcoatRoughness)) / (4.0 * dot(wo, wm));
    }
    return pdf;
}

bool clearcoatedSample(MaterialData m, vec3 wo, vec3 u, out BsdfSample s) {
    float p = clearcoatProbability(m, wo);
    vec3 wi;
    if (u.z < p) {
        if (m.clearcoatRoughness < kSmooth) {
            s = BsdfSample(vec3(-wo.x, -wo.y, wo.z), vec3(clearcoatFresnel(m, wo.z) / p), 0.0, true);
            return true;
        }
        s = BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
        wi = reflectLocal(wo, ggxSampleVisibleNormal(wo, ggxAlpha(m.clearcoatRoughness), u.xy));
    } else {
        // u.z, rescaled to the base's share, is the base's own lobe choice.
        float v = min((u.z - p) / (1.0 - p), 0.99999994);
        if (!sheenLayerSample(m, wo, vec3(u.xy, v), s)) return false;
        if (s.delta) {
            s.weight *= clearcoatTransmittance(m, wo, s.wi) / (1.0 - p);
            return true;
        }
        wi = s.wi;
    }
    if (wi.z <= 0.0) return false;
    float pdf = clearcoatedPdf(m, wo, wi);
    s = BsdfSample(wi, pdf > 0.0 ? clearcoatedEval(m, wo, wi) / pdf : vec3(0.0), pdf, false);
    return pdf > 0.0;
}

// ---- dispatch ----

// wo below the shading frame's horizon (a view direction under an interpolated normal) has f = 0 and
// no samples: the models' formulas assume wo.z > 0 and would give negative or NaN values there. So a
// path that arrives there ends, in nee and bsdf (bsdfSample fails) as in bdpt; naive, which samples
// diffuse surfaces itself, checks the same.
vec3 bsdfEval(MaterialData m, vec3 wo, vec3 wi, float eta) {
    if (!(wo.z > 0.0)) return vec3(0.0);
#if HAS_TYPE(MATERIAL_CONDUCTOR)
    if (m.type == MATERIAL_CONDUCTOR) return conductorEval(m, wo, wi);
#endif
#if HAS_TYPE(MATERIAL_PLASTIC)
    if (m.type == MATERIAL_PLASTIC) return plasticEval(m, wo, wi);
#endif
#if HAS_TYPE(MATERIAL_DIELECTRIC)
    if (m.type == MATERIAL_DIELECTRIC) return dielectricEval(m, wo, wi, eta);
#endif
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    if (m.type == MATERIAL_METALLIC_ROUGHNESS) {
#if HAS_CLEARCOAT
        if (m.clearcoat > 0.0) return clearcoatedEval(m, wo, wi);
#endif
        return sheenLayerEval(m, wo, wi);
    }
#endif
#if HAS_TYPE(MATERIAL_UNLIT)
    if (m.type == MATERIAL_UNLIT) return vec3(0.0);
#endif
    return wi.z > 0.0 ? m.diffuse / PI * wi.z : vec3(0.0);
}

float bsdfPdf(MaterialData m, vec3 wo, vec3 wi, float eta) {
    if (!(wo.z > 0.0)) return 0.0;
#if HAS_TYPE(MATERIAL_CONDUCTOR)
    if (m.type == MATERIAL_CONDUCTOR) return conductorPdf(m, wo, wi);
#endif
#if HAS_TYPE(MATERIAL_PLASTIC)
    if (m.type == MATERIAL_PLASTIC) return plasticPdf(m, wo, wi);
#endif
#if HAS_TYPE(MATERIAL_DIELECTRIC)
    if (m.type == MATERIAL_DIELECTRIC) return dielectricPdf(m, wo, wi, eta);
#endif
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    if (m.type == MATERIAL_METALLIC_ROUGHNESS) {
#if HAS_CLEARCOAT
        if (m.clearcoat > 0.0) return clearcoatedPdf(m, wo, wi);
#endif
        return sheenLayerPdf(m, wo, wi);
    }
#endif
#if HAS_TYPE(MATERIAL_UNLIT)
    if (m.type == MATERIAL_UNLIT) return 0.0;
#endif
    return wi.z > 0.0 ? wi.z / PI : 0.0;
}

bool bsdfSample(MaterialData m, vec3 wo, vec3 u, float eta, out BsdfSample s) {
    s = BsdfSample(vec3(0.0, 0.0, 1.0), vec3(0.0), 0.0, false);
    if (!(wo.z > 0.0)) return false;
#if HAS_TYPE(MATERIAL_CONDUCTOR)
    if (m.type == MATERIAL_CONDUCTOR) return conductorSample(m, wo, u, s);
#endif
#if HAS_TYPE(MATERIAL_PLASTIC)
    if (m.type == MATERIAL_PLASTIC) return plasticSample(m, wo, u, s);
#endif
#if HAS_TYPE(MATERIAL_DIELECTRIC)
    if (m.type == MATERIAL_DIELECTRIC) return dielectricSample(m, wo, u, eta, s);
#endif
#if HAS_TYPE(MATERIAL_METALLIC_ROUGHNESS)
    if (m.type == MATERIAL_METALLIC_ROUGHNESS) {
#if HAS_CLEARCOAT
        if (m.clearcoat > 0.0) return clearcoatedSample(m, wo, u, s);
#endif
        return sheenLayerSample(m, wo, u, s);
    }
#endif
#if HAS_TYPE(MATERIAL_UNLIT)
    if (m.type == MATERIAL_UNLIT) return false;  // the path ends on it
#endif
    vec3 wi = sampleCosineLocal(u.xy);
    s = BsdfSample(wi, m.diffuse, wi.z / PI, false);
    return wi.z > 0.0;
}
