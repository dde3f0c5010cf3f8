// glTF metallic-roughness materials onto fragpath's four models (README, "glTF"; gltf_internal.h).
#include <algorithm>
#include <map>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "image/rgba8_image.h"
#include "scene/gltf_internal.h"

namespace fp::gltf {

namespace {

glm::vec3 clamp01(const glm::vec3& c) {
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

bool isBlack(const glm::vec3& c) {
    return !(c.x > 0.0f || c.y > 0.0f || c.z > 0.0f);
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

// The mean of a channel's code values over [0, 1]: data maps (metallic, roughness) are linear.
float meanChannel(const Rgba8Image& image, int channel) {
    double sum = 0.0;
    size_t count = image.texels.size() / 4;
    for (size_t i = 0; i < count; ++i) sum += image.texels[i * 4 + size_t(channel)];
    return count ? float(sum / (255.0 * double(count))) : 0.0f;
}

}  // namespace

Material materialFromPbr(const PbrFactors& f, const std::string& name) {
    Material m;
    m.name = name;
    m.diffuse = clamp01(glm::vec3(f.baseColor));
    m.emission = f.emission;
    m.roughness = std::clamp(f.roughness, 0.0f, 1.0f);
    float ior = f.ior ? std::clamp(*f.ior, 1.0f, 4.0f) : 1.5f;
    if (f.metallic >= 0.5f) {
        m.type = MaterialType::Conductor;
        m.specular = m.diffuse;
    } else if (f.transmission > 0.5f) {
        m.type = MaterialType::Dielectric;
        m.ior = ior;
        m.transmission = m.diffuse;
    } else if (f.roughness < 1.0f && !isBlack(f.specular)) {
        m.type = MaterialType::Plastic;
        m.specular = clamp01(f.specular);
        // A coat of index 1 would reflect nothing: like MTL's Ni, only an index above 1 counts.
        m.ior = f.ior && *f.ior > 1.0f ? ior : 1.5f;
    } else {
        m.roughness = 0.0f;  // unused by the Lambertian model; kept at the Material default
    }
    return m;
}

struct MaterialTable::Impl {
    const tinygltf::Model& model;
    const std::string& name;
    const GltfLookup& lookup;
    Scene* scene;

    struct Resolved {
        bool done = false;
        uint32_t index = 0;       // into Scene::materials
        int texcoordSet = -1;     // the TEXCOORD set its texture reads, -1 if it has none
        int64_t untextured = -1;  // the copy for primitives without that set, once made
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
    std::map<int, Loaded> images;                                  // by glTF image
    std::set<int> warned;                                          // images whose problem was warned about
    std::map<int, int32_t> sceneTextures;                          // Scene::textures index, by glTF image
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

    int32_t sceneTexture(int texture) {
        int source = model.textures[size_t(texture)].source;
        auto [it, added] = sceneTextures.emplace(source, int32_t(scene->textures.size()));
        if (added) scene->textures.push_back({images.at(source).file, images.at(source).image});
        return it->second;
    }

    Resolved& resolve(int material) {
        if (material >= int(model.materials.size()))
            throw Error(name + ": materials[" + std::to_string(material) + "] does not exist");
        Resolved& r = resolved[material < 0 ? resolved.size() - 1 : size_t(material)];
        if (r.done) return r;
        r.done = true;
        const std::string kIgnoreMap = "ignoring the map";
        PbrFactors f;
        const tinygltf::Material* g = material >= 0 ? &model.materials[size_t(material)] : nullptr;
        if (g) {
            const tinygltf::PbrMetallicRoughness& pbr = g->pbrMetallicRoughness;
            for (int c = 0; c < 4 && size_t(c) < pbr.baseColorFactor.size(); ++c)
                f.baseColor[c] = float(pbr.baseColorFactor[size_t(c)]);
            f.metallic = float(pbr.metallicFactor);
            f.roughness = float(pbr.roughnessFactor);
            for (int c = 0; c < 3 && size_t(c) < g->emissiveFactor.size(); ++c)
                f.emission[c] = float(g->emissiveFactor[size_t(c)]);
            f.emission *= float(
                extensionNumber(g->extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0));
            f.transmission = float(
                extensionNumber(g->extensions, "KHR_materials_transmission", "transmissionFactor", 0.0));
            if (g->extensions.count("KHR_materials_ior")) {
                f.ior = float(extensionNumber(g->extensions, "KHR_materials_ior", "ior", 1.5));
                if (*f.ior == 0.0f || *f.ior > 4.0f)
                    tally("KHR_materials_ior outside [1, 4] clamped into it", material);
            }
            auto specular = g->extensions.find("KHR_materials_specular");
            if (specular != g->extensions.end() && specular->second.IsObject()) {
                f.specular = glm::vec3(1.0f);
                if (specular->second.Has("specularColorFactor")) {
                    const tinygltf::Value& color = specular->second.Get("specularColorFactor");
                    for (int c = 0; c < 3 && size_t(c) < color.ArrayLen(); ++c)
                        f.specular[c] = float(color.Get(c).GetNumberAsDouble());
                }
                f.specular *=
                    float(extensionNumber(g->extensions, "KHR_materials_specular", "specularFactor", 1.0));
                if (extensionTexture(g->extensions, "KHR_materials_specular", "specularTexture") >= 0 ||
                    extensionTexture(g->extensions, "KHR_materials_specular", "specularColorTexture") >= 0)
                    tally("specularTexture and specularColorTexture not supported yet, ignored", material);
            }

            // Maps the models cannot use per texel yet: their mean stands in, so that a mostly
            // non-metallic or mostly dark map does not turn into a metal or a glowing surface.
            if (pbr.metallicRoughnessTexture.index >= 0) {
                const Loaded* map = image(pbr.metallicRoughnessTexture.index, material,
                                          "metallicRoughnessTexture", kIgnoreMap);
                if (map && map->problem.empty()) {
                    f.roughness *= meanChannel(map->image, 1);  // green
                    f.metallic *= meanChannel(map->image, 2);   // blue
                    tally(
                        "metallicRoughnessTexture not supported yet: the factors are multiplied by its mean",
                        material);
                }
            }
            if (g->emissiveTexture.index >= 0) {
                const Loaded* map = image(g->emissiveTexture.index, material, "emissiveTexture", kIgnoreMap);
                if (map && map->problem.empty()) {
                    f.emission *= meanLinearColor(map->image);
                    tally(
                        "emissiveTexture not supported yet: emission is emissiveFactor times its mean colour",
                        material);
                }
            }
            int transmissionTexture =
                extensionTexture(g->extensions, "KHR_materials_transmission", "transmissionTexture");
            if (transmissionTexture >= 0) {
                const Loaded* map = image(transmissionTexture, material, "transmissionTexture", kIgnoreMap);
                if (map && map->problem.empty()) {
                    f.transmission *= meanChannel(map->image, 0);  // red
                    tally(
                        "transmissionTexture not supported yet: transmissionFactor is multiplied by its mean",
                        material);
                }
            }
            if (g->normalTexture.index >= 0) tally("normalTexture not supported yet, ignored", material);
            if (g->occlusionTexture.index >= 0)
                tally("occlusionTexture ignored (a path tracer computes occlusion itself)", material);
            if (g->alphaMode == "MASK" || g->alphaMode == "BLEND")
                tally("alphaMode MASK and BLEND not supported yet: drawn opaque", material);
        }

        Material m = materialFromPbr(f, g ? (g->name.empty() ? label(material) : g->name) : "glTF default");
        if (g && g->pbrMetallicRoughness.baseColorTexture.index >= 0) {
            const tinygltf::TextureInfo& info = g->pbrMetallicRoughness.baseColorTexture;
            bool textured = m.type == MaterialType::Diffuse || m.type == MaterialType::Plastic;
            const Loaded* map = image(info.index, material, "baseColorTexture",
                                      textured ? "showing a magenta and black checker instead" : kIgnoreMap);
            if (map && textured) {
                m.diffuseTexture = sceneTexture(info.index);
                r.texcoordSet = info.texCoord;
                // The checker shows as it is whatever the factor was, as for a missing map_Kd.
                if (!map->problem.empty()) m.diffuse = glm::vec3(1.0f);
                if (info.extensions.count("KHR_texture_transform"))
                    tally("KHR_texture_transform not supported yet, ignored", material);
                int sampler = model.textures[size_t(info.index)].sampler;
                if (sampler >= 0 && size_t(sampler) < model.samplers.size() &&
                    (model.samplers[size_t(sampler)].wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT ||
                     model.samplers[size_t(sampler)].wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT))
                    tally("texture wrap modes other than REPEAT drawn as REPEAT", material);
            } else if (map && map->problem.empty()) {
                // Metals and glass do not read textures: their colour is the texture's mean.
                glm::vec3 mean = meanLinearColor(map->image);
                m.diffuse *= mean;
                m.specular *= mean;
                m.transmission *= mean;
                tally("baseColorTexture on metals and glass not supported yet: its mean colour used",
                      material);
            }
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
        PbrFactors f;
        for (int c = 0; c < 4 && size_t(c) < g.pbrMetallicRoughness.baseColorFactor.size(); ++c)
            f.baseColor[c] = float(g.pbrMetallicRoughness.baseColorFactor[size_t(c)]);
        f.metallic = float(g.pbrMetallicRoughness.metallicFactor);
        f.roughness = float(g.pbrMetallicRoughness.roughnessFactor);
        scene->materials.push_back(materialFromPbr(f, g.name.empty() ? impl_->label(int(i)) : g.name));
    }
}

MaterialTable::~MaterialTable() = default;

int MaterialTable::texcoordSet(int gltfMaterial) {
    return impl_->resolve(gltfMaterial).texcoordSet;
}

uint32_t MaterialTable::use(int gltfMaterial, bool hasTexcoords) {
    Impl::Resolved& r = impl_->resolve(gltfMaterial);
    if (r.texcoordSet < 0 || hasTexcoords) return r.index;
    // Without texture coordinates a texture cannot be looked up: a copy with the texture's mean colour
    // keeps the surface's average albedo (as the OBJ loader does).
    ++r.withoutTexcoords;
    if (r.untextured < 0) {
        Material copy = impl_->scene->materials[r.index];
        copy.diffuse *= meanLinearColor(impl_->scene->textures[size_t(copy.diffuseTexture)].image);
        copy.diffuseTexture = -1;
        r.untextured = int64_t(impl_->scene->materials.size());
        impl_->scene->materials.push_back(copy);
        impl_->tally("primitives without the TEXCOORD_" + std::to_string(r.texcoordSet) +
                         " their texture needs: baseColorFactor times the texture's mean colour",
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
