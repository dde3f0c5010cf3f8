#include <algorithm>
#include <cmath>

#include "scene/obj_mesh.h"
#include "scene/triangulate.h"

namespace fp {

namespace {

// Whether every corner of the face gives a texture coordinate (the face's are then in *uv); a face with
// a NaN or infinite one is counted as a repair and gets none.
bool faceTexcoords(const ObjMesh& mesh, const ObjFace& face, MeshRepairs* repairs,
                   std::vector<glm::vec2>* uv) {
    const ObjCorner* corners = &mesh.corners[face.firstCorner];
    uv->clear();
    for (uint32_t i = 0; i < face.cornerCount; ++i) {
        if (corners[i].texcoord < 0) return false;
        size_t t = static_cast<size_t>(corners[i].texcoord);
        glm::vec2 stored(mesh.texcoords[t]);
        if (!mesh.texcoordFinite[t] || !std::isfinite(stored.x) || !std::isfinite(stored.y)) {
            repairs->badTexcoords.add(face.line);
            return false;
        }
        uv->push_back(stored);
    }
    return true;
}

}  // namespace

std::vector<Triangle> buildTriangles(const ObjMesh& mesh, MeshRepairs* repairs,
                                     std::vector<int>* noTexcoordLine) {
    // Positions as the renderer will store them (float), so that the degeneracy test judges exactly the
    // triangles downstream stages see.
    std::vector<glm::dvec3> stored(mesh.positions.size());
    std::vector<bool> finite(mesh.positions.size()), inRange(mesh.positions.size());
    for (size_t i = 0; i < stored.size(); ++i) {
        glm::vec3 p(mesh.positions[i]);
        finite[i] = mesh.positionFinite[i] && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
        stored[i] = glm::dvec3(p);
        inRange[i] =
            std::max({std::abs(stored[i].x), std::abs(stored[i].y), std::abs(stored[i].z)}) <= kMaxCoordinate;
    }

    std::vector<Triangle> triangles;
    triangles.reserve(mesh.corners.size());
    noTexcoordLine->reserve(noTexcoordLine->size() + mesh.corners.size());
    std::vector<glm::dvec3> polygon;
    std::vector<glm::vec2> uv;
    for (const ObjFace& face : mesh.faces) {
        const ObjCorner* corners = &mesh.corners[face.firstCorner];
        size_t expected = face.cornerCount - 2;  // triangles a polygon of this size yields

        bool allFinite = true, allInRange = true;
        polygon.clear();
        for (uint32_t i = 0; i < face.cornerCount; ++i) {
            allFinite = allFinite && finite[corners[i].vertex];
            allInRange = allInRange && inRange[corners[i].vertex];
            polygon.push_back(stored[corners[i].vertex]);
        }
        if (!allFinite) {
            repairs->nonFinite.add(face.line, expected);
            continue;
        }
        if (!allInRange) {
            repairs->outOfRange.add(face.line, expected);
            continue;
        }

        bool textured = faceTexcoords(mesh, face, repairs, &uv);
        std::vector<std::array<uint32_t, 3>> pieces = triangulate(polygon);
        if (pieces.empty()) repairs->degenerate.add(face.line, expected);
        bool badNormal = false;
        for (const std::array<uint32_t, 3>& piece : pieces) {
            Triangle t;
            for (int k = 0; k < 3; ++k) t.p[k] = glm::vec3(polygon[piece[k]]);
            const glm::dvec3 &p0 = polygon[piece[0]], &p1 = polygon[piece[1]], &p2 = polygon[piece[2]];
            glm::vec3 geometric;
            if (isDegenerate(p0, p1, p2) || !unitVector(glm::cross(p1 - p0, p2 - p0), &geometric)) {
                repairs->degenerate.add(face.line);
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                int32_t n = corners[piece[k]].normal;
                if (n < 0) {
                    t.n[k] = geometric;  // the file gives no normal here: flat shading
                } else if (!mesh.normalFinite[static_cast<size_t>(n)] ||
                           !unitVector(mesh.normals[static_cast<size_t>(n)], &t.n[k])) {
                    t.n[k] = geometric;
                    badNormal = true;
                }
            }
            if (textured)
                for (int k = 0; k < 3; ++k) t.uv[k] = uv[piece[k]];
            t.material = static_cast<uint32_t>(face.materialSlot + 1);
            triangles.push_back(t);
            noTexcoordLine->push_back(textured ? 0 : face.line);
        }
        if (badNormal) repairs->badNormals.add(face.line);
    }
    return triangles;
}

}  // namespace fp
