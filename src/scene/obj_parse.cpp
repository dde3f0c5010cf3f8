#include "scene/obj_parse.h"

#include <map>
#include <set>

#include "core/error.h"
#include "core/log.h"
#include "scene/mtl.h"
#include "scene/obj_mesh.h"
#include "scene/obj_scan.h"
#include "scene/text_file.h"
#include "scene/text_syntax.h"

namespace fp {

namespace {

std::string quotedList(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out;
}

// Every material of every library the file names, in order. Missing or unreadable libraries are
// warned about (and their materials will be undefined, so faces using them fall back to the default).
std::vector<Material> loadLibraries(const ObjScan& scan, const std::string& name, const MtlLookup& lookup) {
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
            std::vector<Material> more = parseMtl(library->bytes, library->name);
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

// Why no triangle is left, for the error message.
std::string droppedSummary(const ObjScan& scan, const MeshRepairs& repairs) {
    std::vector<std::string> parts;
    if (scan.shortFaces.count())
        parts.push_back(scan.shortFaces.describe("skipped", "face", "with fewer than 3 vertices"));
    if (repairs.nonFinite.count())
        parts.push_back(repairs.nonFinite.describe("dropped", "triangle", "with NaN or infinite vertices"));
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
    scene.triangles = buildTriangles(mesh, &repairs);
    if (scene.triangles.empty())
        throw Error(name + ": no valid triangle left (" + droppedSummary(scan, repairs) + ")");

    // Materials only now: a file rejected for its geometry should not first warn about its materials.
    scene.materials = loadLibraries(scan, name, lookup);
    std::vector<uint32_t> bySlot = resolveMaterials(mesh, name, &scene.materials);
    for (Triangle& t : scene.triangles) t.material = bySlot[t.material];

    scan.shortFaces.report(name, "skipped", "face", "with fewer than 3 vertices");
    repairs.nonFinite.report(name, "dropped", "triangle", "with NaN or infinite vertex coordinates");
    repairs.degenerate.report(name, "dropped", "degenerate (zero-area) triangle");
    repairs.badNormals.report(name, "used the geometric normal on", "face",
                              "with zero or NaN vertex normals");
    return scene;
}

}  // namespace fp
