#include "scene/obj_parse.h"

#include <filesystem>
#include <map>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "image/rgba8_image.h"
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

// A map_Kd statement of a library, with what is needed to find its file and to name it in messages.
struct TextureRef {
    std::string libraryFile;  // as the mtllib statement gave it (relative to the OBJ)
    std::string libraryName;  // as the lookup named it (for messages)
    MtlTexture texture;
};

// Every material of every library the file names, in order; their diffuseTexture indexes `textures`.
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
                if (m.diffuseTexture >= 0) m.diffuseTexture += static_cast<int32_t>(textures->size());
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

// Loads the textures of the materials some triangle uses (each file once) into scene->textures and
// points the materials at them; unused materials lose theirs, so that an unused broken map costs nothing.
// A texture file is relative to its MTL library. A texture that is missing or not an image gets one
// warning naming the library, line, material and file, and the magenta and black checker in its place
// (image/rgba8_image.h); the materials showing it get Kd 1, so the checker shows as it is whatever their
// Kd was (a missing texture's colour is lost anyway, and a tinted checker is harder to recognise).
void loadTextures(const std::vector<TextureRef>& refs, const MtlLookup& lookup, Scene* scene) {
    std::vector<bool> used = usedMaterials(*scene);
    std::map<std::string, int32_t> loaded;  // by path relative to the OBJ
    std::set<int32_t> checkers;             // scene->textures that stand in for a file
    for (size_t m = 0; m < scene->materials.size(); ++m) {
        Material& material = scene->materials[m];
        int32_t& index = material.diffuseTexture;
        if (index < 0) continue;
        if (!used[m]) {
            index = -1;
            continue;
        }
        const TextureRef& ref = refs[static_cast<size_t>(index)];
        fs::path file(ref.texture.file);
        std::string path = (file.is_absolute() ? file : fs::path(ref.libraryFile).parent_path() / file)
                               .lexically_normal()
                               .string();
        auto [it, added] = loaded.emplace(path, static_cast<int32_t>(scene->textures.size()));
        index = it->second;
        if (!added) continue;
        std::string problem;
        std::optional<LibraryFile> bytes = lookup(path);
        if (!bytes) {
            fs::path lookedFor = file.is_absolute() ? file : fs::path(ref.libraryName).parent_path() / file;
            problem = "texture '" + ref.texture.file + "' not found or unreadable (looked for " +
                      lookedFor.string() + ")";
        } else {
            try {
                scene->textures.push_back({bytes->name, decodeRgba8(bytes->bytes, bytes->name)});
                continue;
            } catch (const Error& e) {
                problem = e.what();
            }
        }
        warn(ref.libraryName + ":" + std::to_string(ref.texture.line) + ": material '" + material.name +
             "': map_Kd " + problem + "; showing a magenta and black checker instead");
        checkers.insert(index);
        scene->textures.push_back({"missing texture " + path, missingTextureChecker()});
    }
    for (Material& material : scene->materials)
        if (checkers.count(material.diffuseTexture)) material.diffuse = glm::vec3(1.0f);
}

// Triangles without texture coordinates cannot look a texture up: they get a copy of their material
// without it, whose Kd is multiplied by the texture's mean linear colour (so the surface keeps the
// texture's average albedo). One warning counts them.
void untextureFacesWithoutTexcoords(const std::vector<int>& noTexcoordLine, const std::string& name,
                                    Scene* scene) {
    std::map<uint32_t, uint32_t> copyOf;
    RepairTally faces;
    int lastLine = 0;
    for (size_t i = 0; i < scene->triangles.size(); ++i) {
        Triangle& t = scene->triangles[i];
        int line = noTexcoordLine[i];
        if (line == 0 || scene->materials[t.material].diffuseTexture < 0) continue;
        auto [it, added] = copyOf.emplace(t.material, static_cast<uint32_t>(scene->materials.size()));
        if (added) {
            Material copy = scene->materials[t.material];
            copy.diffuse *= meanLinearColor(scene->textures[static_cast<size_t>(copy.diffuseTexture)].image);
            copy.diffuseTexture = -1;
            scene->materials.push_back(copy);
        }
        t.material = it->second;
        if (line != lastLine) faces.add(line);  // a polygon's triangles count once
        lastLine = line;
    }
    // A material left to no triangle needs no texture (the renderer then compiles no lookups).
    std::vector<bool> used = usedMaterials(*scene);
    for (size_t m = 0; m < used.size(); ++m)
        if (!used[m]) scene->materials[m].diffuseTexture = -1;
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
