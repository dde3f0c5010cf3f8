// glTF metallic-roughness materials onto fragpath's (docs/materials.md, the material table; gltf_internal.h).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/error.h"
#include "core/log.h"
#include "image/rgba8_image.h"
#include "scene/gltf_internal.h"
#include "scene/material_maps.h"

namespace fp::gltf {

namespace {

glm::vec3 clamp01(const glm::vec3& c) {
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

// A number an extension object holds, or `fallback`.
double extensionNumber(const tinygltf::ExtensionMap& extensions, const char* extension, const char* key,
                       double fallback) {
    auto it = extensions.find(extension);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

// A texture index inside an extension object ({"index": i, ...}), or -1.
int extensionTexture(const tinygltf::ExtensionMap& extensions, const char* extension, const char* key) {
    auto it = extensions.find(extension);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return -1;
    const tinygltf::Value& info = it->second.Get(key);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) return -1;
    return info.Get("index").GetNumberAsInt();
}

// An RGB array an extension object holds, or `fallback` (also for an array that is not three numbers).
glm::vec3 extensionColor(const tinygltf::ExtensionMap& extensions, const char* extension, const char* key,
                         glm::vec3 fallback) {
    auto it = extensions.find(extension);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) return fallback;
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
        if (!v.Get(i).IsNumber()) return fallback;
        c[i] = float(v.Get(i).GetNumberAsDouble());
    }
    return c;
}

// KHR_materials_volume's absorption coefficient, sigma_a = -ln(attenuationColor) / attenuationDistance
// per unit length (the extension's definition of Beer-Lambert attenuation), 0 without the extension,
// with the default infinite distance, or for a thin-walled material (thicknessFactor 0, the default:
// the extension's rule; any other thickness is a rasterizer's hint, which a path tracer that measures
// the path inside has no use for). A channel of colour 0 absorbs everything: a large finite coefficient
// (1e4 per unit) stands for it.
glm::vec3 absorptionOf(const tinygltf::ExtensionMap& extensions) {
    const char* kVolume = "KHR_materials_volume";
    double distance = extensionNumber(extensions, kVolume, "attenuationDistance", HUGE_VAL);
    double thickness = extensionNumber(extensions, kVolume, "thicknessFactor", 0.0);
    if (!extensions.count(kVolume) || !(thickness > 0.0) || !(distance > 0.0) || !std::isfinite(distance))
        return glm::vec3(0.0f);
    glm::vec3 colour = clamp01(extensionColor(extensions, kVolume, "attenuationColor", glm::vec3(1.0f)));
    glm::vec3 sigma;
    for (int c = 0; c < 3; ++c)
        sigma[c] = colour[c] > 0.0f ? float(-std::log(double(colour[c])) / distance) : 1e4f;
    return sigma;
}

}  // namespace

Material materialFromPbr(const PbrFactors& f, const std::string& name) {
    Material m;
    m.name = name;
    m.diffuse = clamp01(glm::vec3(f.baseColor));
    m.emission = f.emission;
    m.roughness = std::clamp(f.roughness, 0.0f, 1.0f);
    m.alpha = std::clamp(f.baseColor.a, 0.0f, 1.0f);
    m.alphaMode = f.alphaMode;
    m.alphaCutoff = f.alphaCutoff;
    m.doubleSided = f.doubleSided;
    if (f.unlit) {
        // KHR_materials_unlit: the base colour as seen, nothing else (not a light, so no emission).
        m.type = MaterialType::Unlit;
        m.emission = glm::vec3(0.0f);
        return m;
    }
    float ior = f.ior ? std::clamp(*f.ior, 1.0f, 4.0f) : 1.5f;
    if (f.transmission * (1.0f - std::clamp(f.metallic, 0.0f, 1.0f)) > 0.5f) {
        // KHR_materials_transmission with KHR_materials_ior: glass (refraction into the mesh's volume,
        // its index the ior), tinted by the base colour, where over half the surface transmits (glTF:
        // transmission applies to the dielectric part, 1 - metallic).
        m.type = MaterialType::Dielectric;
        m.ior = ior;
        m.transmission = m.diffuse;
        m.absorption = f.absorption;
        return m;
    }
    m.type = MaterialType::MetallicRoughness;
    m.metallic = std::clamp(f.metallic, 0.0f, 1.0f);
    // A coat of index 1 would reflect nothing: like MTL's Ni, only an index above 1 counts.
    m.ior = f.ior && *f.ior > 1.0f ? ior : 1.5f;
    // A tint above 1 would reflect more than arrives at grazing angles, where the Fresnel factor is 1.
    m.specularColor = clamp01(f.specularColor);
    m.clearcoat = std::clamp(f.clearcoat, 0.0f, 1.0f);
    m.clearcoatRoughness = std::clamp(f.clearcoatRoughness, 0.0f, 1.0f);
    m.sheenColor = clamp01(f.sheenColor);
    m.sheenRoughness = std::clamp(f.sheenRoughness, 0.0f, 1.0f);
    return m;
}

namespace {

// The factors of glTF material g, without its textures.
PbrFactors factorsOf(const tinygltf::Material& g) {
    PbrFactors f;
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    for (int c = 0; c < 4 && size_t(c) < pbr.baseColorFactor.size(); ++c)
        f.baseColor[c] = float(pbr.baseColorFactor[size_t(c)]);
    f.metallic = float(pbr.metallicFactor);
    f.roughness = float(pbr.roughnessFactor);
    for (int c = 0; c < 3 && size_t(c) < g.emissiveFactor.size(); ++c)
        f.emission[c] = float(g.emissiveFactor[size_t(c)]);
    f.emission *=
        float(extensionNumber(g.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0));
    f.transmission =
        float(extensionNumber(g.extensions, "KHR_materials_transmission", "transmissionFactor", 0.0));
    if (g.extensions.count("KHR_materials_ior"))
        f.ior = float(extensionNumber(g.extensions, "KHR_materials_ior", "ior", 1.5));
    const char* kSpecular = "KHR_materials_specular";
    f.specularColor = float(extensionNumber(g.extensions, kSpecular, "specularFactor", 1.0)) *
                      extensionColor(g.extensions, kSpecular, "specularColorFactor", glm::vec3(1.0f));
    f.absorption = absorptionOf(g.extensions);
    f.unlit = g.extensions.count("KHR_materials_unlit") > 0;
    const char* kClearcoat = "KHR_materials_clearcoat";
    f.clearcoat = float(extensionNumber(g.extensions, kClearcoat, "clearcoatFactor", 0.0));
    f.clearcoatRoughness = float(extensionNumber(g.extensions, kClearcoat, "clearcoatRoughnessFactor", 0.0));
    const char* kSheen = "KHR_materials_sheen";
    f.sheenColor = extensionColor(g.extensions, kSheen, "sheenColorFactor", glm::vec3(0.0f));
    f.sheenRoughness = float(extensionNumber(g.extensions, kSheen, "sheenRoughnessFactor", 0.0));
    f.alphaMode = g.alphaMode == "MASK"    ? AlphaMode::Mask
                  : g.alphaMode == "BLEND" ? AlphaMode::Blend
                                           : AlphaMode::Opaque;
    f.alphaCutoff = float(g.alphaCutoff);
    f.doubleSided = g.doubleSided;
    return f;
}

}  // namespace

struct MaterialTable::Impl {
    const tinygltf::Model& model;
    const std::string& name;
    const GltfLookup& lookup;
    Scene* scene;

    struct Resolved {
        bool done = false;
        uint32_t index = 0;           // into Scene::materials
        std::vector<UvSlot> uvSlots;  // the (set, transform) pairs its maps read, in order of first use
        int64_t untextured = -1;      // the copy for primitives without those sets, once made
        size_t withoutTexcoords = 0;
    };
    std::vector<Resolved> resolved;  // per glTF material, then the default material
    // A glTF image as loaded: decoded, or (missing, or not an image stb_image reads) the magenta and
    // black checker with the reason, for the user of the texture to warn about.
    struct Loaded {
        Rgba8Image image;
        std::string problem;  // empty when the image loaded
        std::string file;     // the file or the part of the glTF it came from, for Texture::name
    };
    std::map<int, Loaded> images;  // by glTF image
    std::set<int> warned;          // images whose problem was warned about
    // Scene::textures index, by glTF image, how it is sampled and the uv slot that reads it.
    std::map<std::tuple<int, TextureWrap, TextureWrap, bool, int>, int32_t> sceneTextures;
    std::map<std::string, std::vector<std::string>> ignoredKinds;  // what was ignored -> on which materials

    Impl(const tinygltf::Model& m, const std::string& n, const GltfLookup& l, Scene* s)
        : model(m), name(n), lookup(l), scene(s), resolved(m.materials.size() + 1) {}

    std::string label(int material) const {
        if (material < 0) return "the default material";
        const std::string& own = model.materials[size_t(material)].name;
        std::string index = "materials[" + std::to_string(material) + "]";
        return own.empty() ? index : "'" + own + "' (" + index + ")";
    }

    void tally(const std::string& what, int material) {
        std::vector<std::string>& on = ignoredKinds[what];
        std::string l = label(material);
        if (std::find(on.begin(), on.end(), l) == on.end()) on.push_back(l);
    }

    // The image of glTF texture `texture`, or nullptr (with a tally) if the texture has no source we can
    // read. `slot` names the map ("baseColorTexture") for the warning a broken image gets, once.
    const Loaded* image(int texture, int material, const std::string& slot, const std::string& consequence) {
        if (texture < 0 || size_t(texture) >= model.textures.size())
            throw Error(name + ": " + label(material) + " uses textures[" + std::to_string(texture) +
                        "], which does not exist");
        int source = model.textures[size_t(texture)].source;
        if (source < 0) {
            tally(
                "textures without an image fragpath can read (KHR_texture_basisu? EXT_texture_webp?) ignored",
                material);
            return nullptr;
        }
        if (size_t(source) >= model.images.size())
            throw Error(name + ": textures[" + std::to_string(texture) + "] refers to images[" +
                        std::to_string(source) + "], which does not exist");
        auto found = images.find(source);
        if (found == images.end()) found = images.emplace(source, load(source)).first;
        const Loaded& loaded = found->second;
        // Like a missing map_Kd: a warning (an error with --strict), once per image, and the checker.
        if (!loaded.problem.empty() && warned.insert(source).second)
            warn(name + ": " + label(material) + ": " + slot + ": " + loaded.problem + "; " + consequence);
        return &loaded;
    }

    Loaded load(int source) {
        const tinygltf::Image& img = model.images[size_t(source)];
        std::string where = name + ": images[" + std::to_string(source) + "]";
        Loaded loaded;
        loaded.file = where;
        std::string bytes;
        if (img.bufferView >= 0) {
            bytes = std::string(bufferViewBytes(model, img.bufferView, name));
        } else if (!img.image.empty()) {  // a data URI tinygltf decoded (keepEncodedImage)
            bytes.assign(img.image.begin(), img.image.end());
        } else if (img.uri.compare(0, 5, "data:") == 0) {
            loaded.problem = "images[" + std::to_string(source) +
                             "] is a data URI of a type fragpath cannot decode (" + img.uri.substr(0, 30) +
                             "...)";
        } else {
            std::string file = percentDecoded(img.uri);
            loaded.file = img.uri;
            std::optional<LibraryFile> read = lookup(file);
            if (read) {
                bytes = std::move(read->bytes);
                loaded.file = read->name;
            } else {
                loaded.problem = "texture file '" + img.uri + "' not found or unreadable (looked for " +
                                 lookedFor(file) + ")";
            }
        }
        if (loaded.problem.empty()) {
            try {
                loaded.image = decodeRgba8(bytes, loaded.file);
                return loaded;
            } catch (const Error& e) {
                loaded.problem = e.what();
            }
        }
        loaded.image = missingTextureChecker();
        loaded.file = "missing texture " + loaded.file;
        return loaded;
    }

    std::string lookedFor(const std::string& file) const {
        std::string directory = name.substr(0, name.find_last_of('/') + 1);
        return file.size() && file[0] == '/' ? file : directory + file;
    }

    // glTF texture `texture` read through uv slot `slot`, as a Scene texture with its sampler's wrap
    // modes and filter (glTF's defaults, REPEAT and linear, without a sampler).
    int32_t sceneTexture(int texture, int slot) {
        const tinygltf::Texture& t = model.textures[size_t(texture)];
        Texture made{images.at(t.source).file, {}};
        if (t.sampler >= 0 && size_t(t.sampler) < model.samplers.size()) {
            const tinygltf::Sampler& sampler = model.samplers[size_t(t.sampler)];
            auto wrap = [](int mode) {
                return mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::ClampToEdge
                       : mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::MirroredRepeat
                                                                       : TextureWrap::Repeat;
            };
            made.wrapS = wrap(sampler.wrapS);
            made.wrapT = wrap(sampler.wrapT);
            // Without mipmaps only the magnification filter means anything here.
            made.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        made.uvSlot = slot;
        auto [it, added] =
            sceneTextures.emplace(std::make_tuple(t.source, made.wrapS, made.wrapT, made.nearest, slot),
                                  int32_t(scene->textures.size()));
        if (added) {
            made.image = images.at(t.source).image;
            scene->textures.push_back(std::move(made));
        }
        return it->second;
    }

    const std::string kIgnoreMap = "ignoring the map";
    const std::string kShowChecker = "showing a magenta and black checker instead";

    // A textureInfo's KHR_texture_transform, uv' = T R S (u, v, 1) in glTF's uv (v down the image):
    // scale, then rotation by `rotation` radians counter-clockwise as seen on the image (u right, v
    // down), then offset; identity without the extension. Throws fp::Error for a non-finite value, or an
    // offset or scale beyond 1e6.
    glm::mat3 textureTransform(const tinygltf::ExtensionMap& extensions, int material) const {
        auto it = extensions.find("KHR_texture_transform");
        if (it == extensions.end() || !it->second.IsObject()) return glm::mat3(1.0f);
        const tinygltf::Value& t = it->second;
        auto pair = [&](const char* key, double fallback) {
            glm::dvec2 v(fallback);
            if (t.Has(key) && t.Get(key).IsArray())
                for (int c = 0; c < 2 && size_t(c) < t.Get(key).ArrayLen(); ++c)
                    v[c] = t.Get(key).Get(c).GetNumberAsDouble();
            return v;
        };
        glm::dvec2 offset = pair("offset", 0.0), scale = pair("scale", 1.0);
        double rotation = extensionNumber(extensions, "KHR_texture_transform", "rotation", 0.0);
        // Beyond 1e6 texture repeats, float texture coordinates no longer tell texels apart.
        auto sane = [](double v) { return std::abs(v) <= 1e6; };
        if (!sane(offset.x) || !sane(offset.y) || !sane(scale.x) || !sane(scale.y) ||
            !std::isfinite(rotation))
            throw Error(name + ": " + label(material) +
                        ": KHR_texture_transform holds a value that is not finite or beyond 1e6");
        const double c = std::cos(rotation), s = std::sin(rotation);
        // Columns. R is u' = c u + s v, v' = -s u + c v: (1, 0) turns towards -v, up the image. The
        // specification's GLSL listing has the transpose, the counter-clockwise rotation of a y-up frame,
        // which turns the other way in glTF's v-down uv; its sample model (TextureTransformTest, whose
        // arrow must point at the green marker), three.js, Babylon.js and Blender's importer all use
        // this one (KhronosGroup/glTF issue 1563, "KHR_texture_transform has the wrong rotation matrix").
        glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
        glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
        glm::dmat3 scaled(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
        return glm::mat3(translate * rotate * scaled);
    }

    // KHR_texture_transform's texCoord, or `fallback` without one; throws fp::Error unless it is an
    // integer from 0 to 255 (a set index: TEXCOORD_n).
    int transformTexCoord(const tinygltf::ExtensionMap& extensions, int material, int fallback) const {
        auto it = extensions.find("KHR_texture_transform");
        if (it == extensions.end() || !it->second.IsObject() || !it->second.Has("texCoord")) return fallback;
        const tinygltf::Value& v = it->second.Get("texCoord");
        double n = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
        if (!(n >= 0.0 && n <= 255.0 && n == std::floor(n)))
            throw Error(name + ": " + label(material) +
                        ": KHR_texture_transform.texCoord must be a TEXCOORD set number from 0 to 255");
        return int(n);
    }

    // glTF texture `info` (a map of `kind`, named `slot`) as a Scene texture index, or -1 (with a
    // warning or a tally) when it cannot be drawn. A missing colour map shows the checker; any other map
    // that cannot be drawn leaves its factor as the spec has it without the texture, times the map's
    // mean where the image could be read (scaleByMapMean: the surface keeps its average look, as
    // without texture coordinates): an image that cannot be read gives the factor alone, a third
    // (TEXCOORD set, KHR_texture_transform) pair in one material the factor times the mean.
    template <class Info>
    int32_t mapTexture(const Info& info, int material, const std::string& slot, MapKind kind, Material* m,
                       Resolved* r, bool* broken = nullptr) {
        if (info.index < 0) return -1;
        const bool colour = kind == MapKind::Diffuse || kind == MapKind::Emission;
        const Loaded* map = image(info.index, material, slot, colour ? kShowChecker : kIgnoreMap);
        if (!map || (!colour && !map->problem.empty())) return -1;
        if (broken) *broken = !map->problem.empty();
        // KHR_texture_transform: its own texCoord overrides the map's.
        UvSlot wanted{transformTexCoord(info.extensions, material, info.texCoord),
                      textureTransform(info.extensions, material)};
        auto same = [&](const UvSlot& u) { return u.set == wanted.set && u.transform == wanted.transform; };
        auto found = std::find_if(r->uvSlots.begin(), r->uvSlots.end(), same);
        if (found == r->uvSlots.end() && r->uvSlots.size() < 2) found = r->uvSlots.insert(found, wanted);
        if (found == r->uvSlots.end()) {
            scaleByMapMean(m, kind, map->image);
            tally(
                "maps needing a third pair of TEXCOORD set and KHR_texture_transform in one material (two "
                "are drawn) replaced by their means",
                material);
            return -1;
        }
        return sceneTexture(info.index, int(found - r->uvSlots.begin()));
    }

    // The texture maps of glTF material g onto m (docs/materials.md, the material table). Glass reads none of
    // the surface maps but emission and normals: its colour and roughness take their maps' means.
    void addMaps(const tinygltf::Material& g, int material, Material* m, Resolved* r) {
        const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
        bool broken = false;
        int32_t base =
            mapTexture(pbr.baseColorTexture, material, "baseColorTexture", MapKind::Diffuse, m, r, &broken);
        // The checker shows as it is whatever the factor was, as for a missing map_Kd.
        if (base >= 0 && broken) m->diffuse = glm::vec3(1.0f);
        int32_t metallicRoughness = mapTexture(pbr.metallicRoughnessTexture, material,
                                               "metallicRoughnessTexture", MapKind::MetallicRoughness, m, r);
        m->emissionTexture =
            mapTexture(g.emissiveTexture, material, "emissiveTexture", MapKind::Emission, m, r);
        m->normalTexture = mapTexture(g.normalTexture, material, "normalTexture", MapKind::Normal, m, r);
        m->normalScale = float(g.normalTexture.scale);
        if (g.occlusionTexture.index >= 0)
            tally("occlusionTexture ignored (a path tracer computes occlusion itself)", material);
        if (m->type == MaterialType::Dielectric) {
            const std::vector<Texture>& textures = scene->textures;
            if (base >= 0) m->transmission *= meanLinearColor(textures[size_t(base)].image);
            if (metallicRoughness >= 0)
                m->roughness *= meanCodes(textures[size_t(metallicRoughness)].image).g;
            if (base >= 0 || metallicRoughness >= 0)
                tally("baseColorTexture and metallicRoughnessTexture on glass: their means used", material);
            return;
        }
        m->diffuseTexture = base;
        m->metallicRoughnessTexture = metallicRoughness;
        // The base colour texture's alpha is the coverage map (glTF: alpha = factor.a * texture.a).
        if (m->alphaMode != AlphaMode::Opaque && !broken) m->alphaTexture = base;
    }

    // KHR_materials_specular's textures (A: the factor, RGB: the colour) as their means, which multiply
    // the factors; a tint above 1 is clamped (materialFromPbr), and glass takes none of it.
    // The image of the texture an extension of glTF material g names under `key`, if it has one that
    // loaded (a broken one is warned about and ignored).
    const Loaded* extensionImage(const tinygltf::Material& g, int material, const char* extension,
                                 const char* key) {
        int texture = extensionTexture(g.extensions, extension, key);
        const Loaded* map = texture >= 0 ? image(texture, material, key, kIgnoreMap) : nullptr;
        return map && map->problem.empty() ? map : nullptr;
    }

    void specularTextures(const tinygltf::Material& g, int material, PbrFactors* f) {
        const char* kSpecular = "KHR_materials_specular";
        if (!g.extensions.count(kSpecular)) return;
        const Loaded* a = extensionImage(g, material, kSpecular, "specularTexture");
        const Loaded* rgb = extensionImage(g, material, kSpecular, "specularColorTexture");
        if (a) f->specularColor *= meanCodes(a->image).a;
        if (rgb) f->specularColor *= meanLinearColor(rgb->image);
        if (a || rgb)
            tally("KHR_materials_specular textures: the factors are multiplied by their means", material);
        if (glm::any(glm::greaterThan(f->specularColor, glm::vec3(1.0f))))
            tally("KHR_materials_specular: specularFactor * specularColorFactor above 1 clamped to 1",
                  material);
    }

    // KHR_materials_clearcoat's textures (R: the factor, G: the roughness) as their means, which
    // multiply the factors; its normal map is not used (the coat takes the surface's shading normal).
    void clearcoatTextures(const tinygltf::Material& g, int material, PbrFactors* f) {
        const char* kClearcoat = "KHR_materials_clearcoat";
        if (!g.extensions.count(kClearcoat)) return;
        const Loaded* factor = extensionImage(g, material, kClearcoat, "clearcoatTexture");
        const Loaded* roughness = extensionImage(g, material, kClearcoat, "clearcoatRoughnessTexture");
        if (factor) f->clearcoat *= meanCodes(factor->image).r;
        if (roughness) f->clearcoatRoughness *= meanCodes(roughness->image).g;
        if (factor || roughness)
            tally("KHR_materials_clearcoat textures: the factors are multiplied by their means", material);
        if (extensionTexture(g.extensions, kClearcoat, "clearcoatNormalTexture") >= 0)
            tally("clearcoatNormalTexture ignored (the coat takes the surface's normal)", material);
    }

    // KHR_materials_sheen's textures (RGB, sRGB: the colour; A: the roughness) as their means, which
    // multiply the factors.
    void sheenTextures(const tinygltf::Material& g, int material, PbrFactors* f) {
        const char* kSheen = "KHR_materials_sheen";
        if (!g.extensions.count(kSheen)) return;
        const Loaded* colour = extensionImage(g, material, kSheen, "sheenColorTexture");
        const Loaded* roughness = extensionImage(g, material, kSheen, "sheenRoughnessTexture");
        if (colour) f->sheenColor *= meanLinearColor(colour->image);
        if (roughness) f->sheenRoughness *= meanCodes(roughness->image).a;
        if (colour || roughness)
            tally("KHR_materials_sheen textures: the factors are multiplied by their means", material);
    }

    Resolved& resolve(int material) {
        if (material >= int(model.materials.size()))
            throw Error(name + ": materials[" + std::to_string(material) + "] does not exist");
        Resolved& r = resolved[material < 0 ? resolved.size() - 1 : size_t(material)];
        if (r.done) return r;
        r.done = true;
        const tinygltf::Material* g = material >= 0 ? &model.materials[size_t(material)] : nullptr;
        PbrFactors f = g ? factorsOf(*g) : PbrFactors{};
        if (g && g->extensions.count("KHR_materials_ior") && (*f.ior == 0.0f || *f.ior > 4.0f))
            tally("KHR_materials_ior outside [1, 4] clamped into it", material);
        if (g) specularTextures(*g, material, &f);
        if (g) clearcoatTextures(*g, material, &f);
        if (g) sheenTextures(*g, material, &f);
        // The transmission map decides the model, so only its mean can count.
        int transmissionTexture =
            g ? extensionTexture(g->extensions, "KHR_materials_transmission", "transmissionTexture") : -1;
        if (transmissionTexture >= 0) {
            const Loaded* map = image(transmissionTexture, material, "transmissionTexture", kIgnoreMap);
            if (map && map->problem.empty()) {
                f.transmission *= meanCodes(map->image).r;
                tally("transmissionTexture: transmissionFactor is multiplied by its mean", material);
            }
        }
        Material m = materialFromPbr(f, g ? (g->name.empty() ? label(material) : g->name) : "glTF default");
        if (g) addMaps(*g, material, &m, &r);
        if (m.type == MaterialType::Dielectric && f.clearcoat > 0.0f)
            tally("KHR_materials_clearcoat on glass ignored", material);
        if (m.type == MaterialType::Dielectric && f.sheenColor != glm::vec3(0.0f))
            tally("KHR_materials_sheen on glass ignored", material);
        if (m.type == MaterialType::Dielectric && f.specularColor != glm::vec3(1.0f))
            tally("KHR_materials_specular on glass ignored (its reflectance is the exact Fresnel of its ior)",
                  material);
        if (m.type == MaterialType::Unlit) {  // it shows its base colour (and alpha) and nothing else
            m.metallicRoughnessTexture = m.emissionTexture = m.normalTexture = -1;
        }
        if (material >= 0) {
            r.index = uint32_t(material);
            scene->materials[size_t(material)] = m;
        } else {
            r.index = uint32_t(scene->materials.size());
            scene->materials.push_back(m);
        }
        return r;
    }
};

MaterialTable::MaterialTable(const tinygltf::Model& model, const std::string& name, const GltfLookup& lookup,
                             Scene* scene)
    : impl_(std::make_unique<Impl>(model, name, lookup, scene)) {
    // Every glTF material keeps its index; the ones no primitive uses are mapped from their factors
    // alone (their textures are never loaded).
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& g = model.materials[i];
        scene->materials.push_back(
            materialFromPbr(factorsOf(g), g.name.empty() ? impl_->label(int(i)) : g.name));
    }
}

MaterialTable::~MaterialTable() = default;

const std::vector<MaterialTable::UvSlot>& MaterialTable::uvSlots(int gltfMaterial) {
    return impl_->resolve(gltfMaterial).uvSlots;
}

uint32_t MaterialTable::use(int gltfMaterial, bool hasTexcoords) {
    Impl::Resolved& r = impl_->resolve(gltfMaterial);
    if (r.uvSlots.empty() || hasTexcoords) return r.index;
    // Without texture coordinates a texture cannot be looked up: a copy with its maps' means keeps the
    // surface's average look (as the OBJ loader does).
    ++r.withoutTexcoords;
    if (r.untextured < 0) {
        Scene& scene = *impl_->scene;
        r.untextured = int64_t(scene.materials.size());
        scene.materials.push_back(withoutMaps(scene.materials[r.index], scene.textures));
        std::string sets = "TEXCOORD_" + std::to_string(r.uvSlots[0].set);
        if (r.uvSlots.size() > 1 && r.uvSlots[1].set != r.uvSlots[0].set)
            sets += " and TEXCOORD_" + std::to_string(r.uvSlots[1].set);
        impl_->tally("primitives without the " + sets + " their maps need: the factors times the maps' means",
                     gltfMaterial);
    }
    return uint32_t(r.untextured);
}

void MaterialTable::reportIgnored() const {
    for (const auto& [what, materials] : impl_->ignoredKinds) {
        std::string list;
        for (size_t i = 0; i < materials.size() && i < 4; ++i) list += (i ? ", " : "") + materials[i];
        if (materials.size() > 4) list += " and " + std::to_string(materials.size() - 4) + " more";
        warn(impl_->name + ": " + what + " (" + (materials.size() == 1 ? "material " : "materials ") + list +
             ")");
    }
}

}  // namespace fp::gltf
