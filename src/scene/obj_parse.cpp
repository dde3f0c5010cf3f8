#include "scene/obj_parse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "image/rgba8_image.h"
#include "scene/material_maps.h"
#include "scene/mtl.h"
#include "scene/obj_mesh.h"
#include "scene/obj_scan.h"
#include "scene/text_file.h"
#include "scene/text_syntax.h"

namespace fp {

namespace {

namespace fs = std::filesystem;

std::string quotedList(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out;
}

// A texture map statement of a library, with what is needed to find its file(s) and to name them in
// messages.
struct TextureRef {
    std::string libraryFile;  // as the mtllib statement gave it (relative to the OBJ)
    std::string libraryName;  // as the lookup named it (for messages)
    MtlTexture texture;
};

// Every material of every library the file names, in order; their *Texture fields index `textures`.
// Missing or unreadable libraries are warned about (and their materials will be undefined, so faces
// using them fall back to the default).
std::vector<Material> loadLibraries(const ObjScan& scan, const std::string& name, const MtlLookup& lookup,
                                    std::vector<TextureRef>* textures) {
    std::vector<Material> materials;
    std::set<std::string> seen;
    std::vector<std::string> missing;
    int firstMissingLine = 0;
    for (const MtlLibraryRef& ref : scan.materialLibraries) {
        // Usually one name, but a statement may list several; a single name may also contain blanks.
        std::vector<std::string> files;
        if (ref.names.find_first_of(" \t") != std::string::npos && lookup(ref.names)) {
            files.push_back(ref.names);
        } else {
            std::vector<std::string_view> words;
            splitWords(ref.names, &words);
            for (std::string_view w : words) files.emplace_back(w);
        }
        for (const std::string& file : files) {
            if (!seen.insert(file).second) continue;
            std::optional<LibraryFile> library = lookup(file);
            if (!library) {
                if (missing.empty()) firstMissingLine = ref.line;
                missing.push_back(file);
                continue;
            }
            std::string reason = nonTextReason(library->bytes);
            if (!reason.empty()) {
                warn(library->name + ": " + reason + "; ignoring this material library");
                continue;
            }
            std::vector<MtlTexture> maps;
            std::vector<Material> more = parseMtl(library->bytes, library->name, &maps);
            for (Material& m : more)
                for (int32_t* index : textureSlots(m))
                    if (*index >= 0) *index += static_cast<int32_t>(textures->size());
            for (const MtlTexture& map : maps) textures->push_back({file, library->name, map});
            materials.insert(materials.end(), more.begin(), more.end());
        }
    }
    if (!missing.empty())
        warn(name + ": material " + (missing.size() == 1 ? "library " : "libraries ") + quotedList(missing) +
             " not found (first at line " + std::to_string(firstMissingLine) +
             "); faces using materials from it get the default material");
    return materials;
}

// Maps every face's usemtl slot to an index in `materials`, appending the default material if some
// face needs it (no usemtl, or a name no library defines).
std::vector<uint32_t> resolveMaterials(const ObjMesh& mesh, const std::string& name,
                                       std::vector<Material>* materials) {
    std::map<std::string, uint32_t> byName;
    for (size_t i = 0; i < materials->size(); ++i)
        byName.emplace((*materials)[i].name, static_cast<uint32_t>(i));  // the first definition wins

    // Index 0 stands for "no usemtl"; slot s is index s + 1 (see buildTriangles).
    constexpr uint32_t kUnresolved = ~0u;
    std::vector<uint32_t> bySlot(mesh.materialNames.size() + 1, kUnresolved);
    std::vector<std::string> undefined;
    for (size_t s = 0; s < mesh.materialNames.size(); ++s) {
        auto it = byName.find(mesh.materialNames[s]);
        if (it != byName.end()) {
            bySlot[s + 1] = it->second;
        } else {
            undefined.push_back(mesh.materialNames[s]);
        }
    }
    RepairTally undefinedFaces;
    bool needDefault = false;
    for (const ObjFace& face : mesh.faces) {
        if (bySlot[static_cast<size_t>(face.materialSlot + 1)] != kUnresolved) continue;
        needDefault = true;
        if (face.materialSlot >= 0) undefinedFaces.add(face.line);
    }
    if (needDefault) {
        uint32_t fallback = static_cast<uint32_t>(materials->size());
        materials->push_back(Material{});
        for (uint32_t& m : bySlot)
            if (m == kUnresolved) m = fallback;
    }
    undefinedFaces.report(name, "gave", "face",
                          "the default material: undefined material " + quotedList(undefined));
    return bySlot;
}

std::vector<bool> usedMaterials(const Scene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const Triangle& t : scene.triangles) used[t.material] = true;
    return used;
}

// The path of a texture file relative to the OBJ (or absolute), from its name relative to the library.
std::string texturePath(const TextureRef& ref, const std::string& file) {
    fs::path f(file);
    return (f.is_absolute() ? f : fs::path(ref.libraryFile).parent_path() / f).lexically_normal().string();
}

// The image in `file` (relative to ref's library), named by `statement` and `line` in errors: throws
// fp::Error naming the library, line and file if it is missing or not an image.
Rgba8Image loadMapFile(const TextureRef& ref, const std::string& file, const std::string& statement, int line,
                       const MtlLookup& lookup) {
    std::string where = ref.libraryName + ":" + std::to_string(line) + ": " + statement + " ";
    std::optional<LibraryFile> bytes = lookup(texturePath(ref, file));
    if (!bytes) {
        fs::path f(file);
        fs::path lookedFor = f.is_absolute() ? f : fs::path(ref.libraryName).parent_path() / f;
        throw Error(where + "texture '" + file + "' not found or unreadable (looked for " +
                    lookedFor.string() + ")");
    }
    try {
        return decodeRgba8(bytes->bytes, bytes->name);
    } catch (const Error& e) {
        throw Error(where + e.what());
    }
}

// One channel of an 8-bit texel as a scalar map reads it (mtl.h: -imfchan): r, g, b, m (the alpha), or
// the luminance (Rec. 709 weights on the codes, rounded: a grey file's value).
uint8_t channelCode(const uint8_t* texel, char channel) {
    switch (channel) {
        case 'r':
            return texel[0];
        case 'g':
            return texel[1];
        case 'b':
            return texel[2];
        case 'm':
            return texel[3];
        default:
            return uint8_t(std::lround(0.2126 * texel[0] + 0.7152 * texel[1] + 0.0722 * texel[2]));
    }
}

bool isGreyscale(const Rgba8Image& image) {
    if (image.fileChannels <= 2) return true;
    for (size_t i = 0; i + 3 < image.texels.size(); i += 4)
        if (image.texels[i] != image.texels[i + 1] || image.texels[i] != image.texels[i + 2]) return false;
    return true;
}

// map_Pr and map_Pm combined into one metallic-roughness texture: G from the first (255 without), B
// from the second (255 without), at the larger of their sizes (nearest texel when they differ).
Rgba8Image metallicRoughnessTexture(const Rgba8Image* roughness, char roughnessChannel,
                                    const Rgba8Image* metallic, char metallicChannel) {
    Rgba8Image out;
    for (const Rgba8Image* image : {roughness, metallic})
        if (image) {
            out.width = std::max(out.width, image->width);
            out.height = std::max(out.height, image->height);
        }
    out.texels.assign(size_t(out.width) * size_t(out.height) * 4, 255);
    auto code = [&](const Rgba8Image* image, char channel, int x, int y) -> uint8_t {
        if (!image) return 255;
        int sx = int(int64_t(x) * image->width / out.width),
            sy = int(int64_t(y) * image->height / out.height);
        return channelCode(&image->texels[(size_t(sy) * size_t(image->width) + size_t(sx)) * 4], channel);
    };
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            uint8_t* texel = &out.texels[(size_t(y) * size_t(out.width) + size_t(x)) * 4];
            texel[0] = 0;
            texel[1] = code(roughness, roughnessChannel, x, y);
            texel[2] = code(metallic, metallicChannel, x, y);
        }
    return out;
}

// Loads the textures of the materials some triangle uses (each file, as each kind of map, once) into
// scene->textures and points the materials at them; unused materials lose theirs, so that an unused
// broken map costs nothing. Texture files are relative to their MTL library. A texture that is missing
// or not an image gets one warning naming the library, line, material and file; a colour map (map_Kd,
// map_Ke, map_Ks) then shows the magenta and black checker (image/rgba8_image.h), with Kd 1 for map_Kd
// so that it shows as it is whatever Kd was (a missing texture's colour is lost anyway, and a tinted
// checker is harder to recognise), while any other map is ignored (a checker of normals, roughness or
// coverage would not look like one). A map_Bump or bump of a greyscale file is a height map: warned
// about and dropped.
void loadTextures(const std::vector<TextureRef>& refs, const MtlLookup& lookup, Scene* scene) {
    std::vector<bool> used = usedMaterials(*scene);
    std::map<std::string, int32_t> loaded;  // by kind, paths relative to the OBJ and channels; -1: refused
    std::set<int32_t> checkers;             // scene->textures that stand in for a file
    for (size_t m = 0; m < scene->materials.size(); ++m) {
        for (int32_t* slot : textureSlots(scene->materials[m])) {
            int32_t& index = *slot;
            if (index < 0) continue;
            if (!used[m]) {
                index = -1;
                continue;
            }
            const TextureRef& ref = refs[static_cast<size_t>(index)];
            const MtlTexture& t = ref.texture;
            std::string key = std::to_string(int(t.kind)) + "|" + std::string(1, t.channel) + "|" +
                              (t.file.empty() ? "" : texturePath(ref, t.file)) + "|" +
                              std::string(1, t.metallicChannel) + "|" +
                              (t.metallicFile.empty() ? "" : texturePath(ref, t.metallicFile));
            auto [it, added] = loaded.emplace(key, static_cast<int32_t>(scene->textures.size()));
            index = it->second;
            if (!added) continue;
            Texture texture;
            texture.name = t.file.empty() ? t.metallicFile : t.file;
            try {
                switch (t.kind) {
                    case MtlTextureKind::Color:
                        texture.image = loadMapFile(ref, t.file, t.statement, t.line, lookup);
                        break;
                    case MtlTextureKind::Normal:
                        texture.image = loadMapFile(ref, t.file, t.statement, t.line, lookup);
                        if (isGreyscale(texture.image)) {
                            warn(ref.libraryName + ":" + std::to_string(t.line) + ": " + t.statement + " '" +
                                 t.file +
                                 "' is a greyscale image, a height (bump) map: height maps are not supported "
                                 "(only tangent-space normal maps), ignored");
                            it->second = index = -1;
                            continue;
                        }
                        break;
                    case MtlTextureKind::Alpha: {
                        texture.image = loadMapFile(ref, t.file, t.statement, t.line, lookup);
                        // Without -imfchan: the file's alpha channel if it has one, else its luminance.
                        const bool hasAlpha =
                            texture.image.fileChannels == 2 || texture.image.fileChannels == 4;
                        const char channel = t.channel ? t.channel : hasAlpha ? 'm' : 'l';
                        for (size_t i = 0; i + 3 < texture.image.texels.size(); i += 4)
                            texture.image.texels[i + 3] = channelCode(&texture.image.texels[i], channel);
                        break;
                    }
                    case MtlTextureKind::MetallicRoughness: {
                        std::optional<Rgba8Image> roughness, metallic;
                        if (!t.file.empty()) roughness = loadMapFile(ref, t.file, "map_Pr", t.line, lookup);
                        if (!t.metallicFile.empty())
                            metallic = loadMapFile(ref, t.metallicFile, "map_Pm", t.metallicLine, lookup);
                        if (roughness && metallic &&
                            (roughness->width != metallic->width || roughness->height != metallic->height))
                            warn(ref.libraryName + ":" + std::to_string(t.metallicLine) + ": map_Pm '" +
                                 t.metallicFile + "' and map_Pr '" + t.file +
                                 "' differ in size; combined at the larger size (nearest texels)");
                        texture.image =
                            metallicRoughnessTexture(roughness ? &*roughness : nullptr, t.channel,
                                                     metallic ? &*metallic : nullptr, t.metallicChannel);
                        if (roughness && metallic) texture.name = t.file + " + " + t.metallicFile;
                        break;
                    }
                }
            } catch (const Error& e) {
                // loadMapFile's message starts "library:line: statement"; the material goes after the line.
                std::string what = e.what();
                size_t line = what.find(": ", ref.libraryName.size());
                what.insert(line == std::string::npos ? 0 : line + 2,
                            "material '" + scene->materials[m].name + "': ");
                if (t.kind != MtlTextureKind::Color) {
                    warn(what + "; ignoring the map");
                    it->second = index = -1;
                    continue;
                }
                warn(what + "; showing a magenta and black checker instead");
                checkers.insert(index);
                texture = {"missing texture " + texturePath(ref, t.file), missingTextureChecker()};
            }
            scene->textures.push_back(std::move(texture));
        }
    }
    for (Material& material : scene->materials)
        if (checkers.count(material.diffuseTexture)) material.diffuse = glm::vec3(1.0f);
}

// Triangles without texture coordinates cannot look a texture up: they get a copy of their material
// without its maps (withoutMaps). One warning counts them.
void untextureFacesWithoutTexcoords(const std::vector<int>& noTexcoordLine, const std::string& name,
                                    Scene* scene) {
    std::map<uint32_t, uint32_t> copyOf;
    RepairTally faces;
    int lastLine = 0;
    for (size_t i = 0; i < scene->triangles.size(); ++i) {
        Triangle& t = scene->triangles[i];
        int line = noTexcoordLine[i];
        if (line == 0 || !scene->materials[t.material].hasTextures()) continue;
        auto [it, added] = copyOf.emplace(t.material, static_cast<uint32_t>(scene->materials.size()));
        if (added) scene->materials.push_back(withoutMaps(scene->materials[t.material], scene->textures));
        t.material = it->second;
        if (line != lastLine) faces.add(line);  // a polygon's triangles count once
        lastLine = line;
    }
    // A material left to no triangle needs no texture (the renderer then compiles no lookups).
    std::vector<bool> used = usedMaterials(*scene);
    for (size_t m = 0; m < used.size(); ++m)
        if (!used[m])
            for (int32_t* slot : textureSlots(scene->materials[m])) *slot = -1;
    faces.report(name, "gave", "face",
                 "of textured materials without texture coordinates (vt) Kd times the texture's mean colour");
}

const char* kOutOfRangeWhy =
    "with vertex coordinates beyond +-1e18 (stray vertices? the renderer's 32-bit squared distances "
    "overflow there)";

// Why no triangle is left, for the error message.
std::string droppedSummary(const ObjScan& scan, const MeshRepairs& repairs) {
    std::vector<std::string> parts;
    if (scan.shortFaces.count())
        parts.push_back(scan.shortFaces.describe("skipped", "face", "with fewer than 3 vertices"));
    if (repairs.nonFinite.count())
        parts.push_back(repairs.nonFinite.describe("dropped", "triangle", "with NaN or infinite vertices"));
    if (repairs.outOfRange.count())
        parts.push_back(repairs.outOfRange.describe("dropped", "triangle", kOutOfRangeWhy));
    if (repairs.degenerate.count())
        parts.push_back(repairs.degenerate.describe("dropped", "degenerate (zero-area) triangle"));
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out;
}

}  // namespace

Scene parseObj(std::string_view bytes, const std::string& name, const MtlLookup& lookup) {
    std::string_view text = requireText(bytes, name);
    ObjScan scan = scanObj(text, name);
    if (scan.faceLines.empty() && scan.shortFaces.count() == 0) throw Error(name + ": contains no faces");

    ObjMesh mesh = readObjMesh(scan, name);
    MeshRepairs repairs;
    Scene scene;
    scene.source = name;
    std::vector<int> noTexcoordLine;
    scene.triangles = buildTriangles(mesh, &repairs, &noTexcoordLine);
    if (scene.triangles.empty())
        throw Error(name + ": no valid triangle left (" + droppedSummary(scan, repairs) + ")");

    // Materials only now: a file rejected for its geometry should not first warn about its materials.
    std::vector<TextureRef> textures;
    scene.materials = loadLibraries(scan, name, lookup, &textures);
    std::vector<uint32_t> bySlot = resolveMaterials(mesh, name, &scene.materials);
    for (Triangle& t : scene.triangles) t.material = bySlot[t.material];
    loadTextures(textures, lookup, &scene);
    untextureFacesWithoutTexcoords(noTexcoordLine, name, &scene);

    scan.shortFaces.report(name, "skipped", "face", "with fewer than 3 vertices");
    repairs.nonFinite.report(name, "dropped", "triangle", "with NaN or infinite vertex coordinates");
    repairs.outOfRange.report(name, "dropped", "triangle", kOutOfRangeWhy);
    repairs.degenerate.report(name, "dropped", "degenerate (zero-area) triangle");
    repairs.badNormals.report(name, "used the geometric normal on", "face",
                              "with zero or NaN vertex normals");
    repairs.badTexcoords.report(name, "used no texture coordinates on", "face", "with NaN or infinite ones");
    return scene;
}

}  // namespace fp
