// tinyobjloader's streaming interface: it reports statements in file order without splitting the file
// into shapes, dropping short faces or limiting polygons to 255 corners (as LoadObj's mesh_t does), so
// each face it reports pairs up with the line the scan recorded for it.
#include <istream>
#include <map>
#include <streambuf>

#include <tiny_obj_loader.h>

#include "core/error.h"
#include "scene/obj_mesh.h"

namespace fp {

namespace {

struct Reader {
    const ObjScan& scan;
    ObjMesh mesh;
    std::map<std::string, int32_t> slots;
    int32_t slot = -1;

    static Reader& of(void* user) { return *static_cast<Reader*>(user); }

    static void vertex(void* user, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t) {
        of(user).mesh.positions.emplace_back(x, y, z);
    }
    static void normal(void* user, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        of(user).mesh.normals.emplace_back(x, y, z);
    }
    static void texcoord(void* user, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        of(user).mesh.texcoords.emplace_back(u, v);
    }
    static void face(void* user, tinyobj::index_t* indices, int count) {
        Reader& r = of(user);
        size_t f = r.mesh.faces.size();
        // Past the scan's faces means the two disagree; the count check after loading reports it.
        int line = f < r.scan.faceLines.size() ? r.scan.faceLines[f] : 0;
        r.mesh.faces.push_back(
            {line, static_cast<uint32_t>(r.mesh.corners.size()), static_cast<uint32_t>(count), r.slot});
        // The scan made every index absolute and 1-based; 0 means "not given".
        for (int i = 0; i < count; ++i)
            r.mesh.corners.push_back({static_cast<uint32_t>(indices[i].vertex_index - 1),
                                      indices[i].normal_index - 1, indices[i].texcoord_index - 1});
    }
    static void material(void* user, const char* name, int) {
        // Names, not tinyobjloader's ids: the MTL libraries are read separately, after the geometry.
        Reader& r = of(user);
        auto [it, added] = r.slots.emplace(name, static_cast<int32_t>(r.mesh.materialNames.size()));
        if (added) r.mesh.materialNames.push_back(name);
        r.slot = it->second;
    }
};

// An input stream's buffer over the scan's text, which std::istringstream would copy (tens of megabytes
// for a million triangles). Only read: the const_cast is for std::streambuf's interface.
struct TextBuffer : std::streambuf {
    explicit TextBuffer(const std::string& text) {
        char* begin = const_cast<char*>(text.data());
        setg(begin, begin, begin + text.size());
    }
};

}  // namespace

ObjMesh readObjMesh(const ObjScan& scan, const std::string& name) {
    Reader reader{scan, {}, {}, -1};
    // The scan counted every element: the arrays are sized once.
    reader.mesh.positions.reserve(scan.vertexFinite.size());
    reader.mesh.normals.reserve(scan.normalFinite.size());
    reader.mesh.texcoords.reserve(scan.texcoordFinite.size());
    reader.mesh.faces.reserve(scan.faceLines.size());
    reader.mesh.corners.reserve(scan.cornerCount);
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = &Reader::vertex;
    callbacks.normal_cb = &Reader::normal;
    callbacks.texcoord_cb = &Reader::texcoord;
    callbacks.index_cb = &Reader::face;
    callbacks.usemtl_cb = &Reader::material;
    TextBuffer buffer(scan.text);
    std::istream stream(&buffer);
    std::string warnings, errors;
    bool ok = tinyobj::LoadObjWithCallback(stream, callbacks, &reader, nullptr, &warnings, &errors);

    ObjMesh& mesh = reader.mesh;
    bool agree = ok && mesh.positions.size() == scan.vertexFinite.size() &&
                 mesh.normals.size() == scan.normalFinite.size() &&
                 mesh.texcoords.size() == scan.texcoordFinite.size() &&
                 mesh.faces.size() == scan.faceLines.size();
    for (const ObjCorner& c : mesh.corners)
        agree = agree && c.vertex < mesh.positions.size() &&
                (c.normal < 0 || static_cast<size_t>(c.normal) < mesh.normals.size()) &&
                (c.texcoord < 0 || static_cast<size_t>(c.texcoord) < mesh.texcoords.size());
    if (!agree)
        throw Error(name + ": internal error: tinyobjloader read the checked file differently (" + errors +
                    ")");
    mesh.positionFinite = scan.vertexFinite;
    mesh.normalFinite = scan.normalFinite;
    mesh.texcoordFinite = scan.texcoordFinite;
    return std::move(reader.mesh);
}

}  // namespace fp
