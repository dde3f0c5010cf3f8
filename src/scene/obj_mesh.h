#pragma once
// The OBJ loader's middle: faces as tinyobjloader read them (from the scan's normalized text), and
// their conversion into validated triangles.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/obj_scan.h"
#include "scene/repair_tally.h"
#include "scene/scene.h"

namespace fp {

struct ObjCorner {
    uint32_t vertex;   // 0-based
    int32_t normal;    // 0-based, -1 if the face gives none
    int32_t texcoord;  // 0-based, -1 if the face gives none
};

struct ObjFace {
    int line;              // in the OBJ file
    uint32_t firstCorner;  // into ObjMesh::corners
    uint32_t cornerCount;  // >= 3
    int32_t materialSlot;  // into ObjMesh::materialNames, -1 before any usemtl
};

struct ObjMesh {
    std::vector<glm::dvec3> positions;
    std::vector<bool> positionFinite;  // from the scan: tinyobjloader reads nan/inf as 0
    std::vector<glm::dvec3> normals;
    std::vector<bool> normalFinite;
    std::vector<glm::dvec2> texcoords;
    std::vector<bool> texcoordFinite;
    std::vector<ObjCorner> corners;
    std::vector<ObjFace> faces;
    std::vector<std::string> materialNames;  // distinct usemtl names, in order of first use
};

// Runs tinyobjloader over the scan's normalized text. Throws fp::Error if the two ever disagree about
// what the file contains (a bug, not bad input).
ObjMesh readObjMesh(const ObjScan& scan, const std::string& name);

// The largest vertex coordinate the renderer takes: it squares distances in 32-bit floats, and beyond
// about 1.8e19 a squared distance overflows to infinity (and the camera that frames such a scene is no
// longer finite). Coordinates that large in a model are stray vertices, not geometry.
constexpr double kMaxCoordinate = 1e18;

struct MeshRepairs {
    RepairTally nonFinite;     // triangles dropped for NaN/infinite vertices
    RepairTally outOfRange;    // triangles dropped for vertex coordinates beyond kMaxCoordinate
    RepairTally degenerate;    // zero-area triangles dropped
    RepairTally badNormals;    // faces whose zero/NaN vertex normals were replaced by the geometric normal
    RepairTally badTexcoords;  // faces with NaN/infinite texture coordinates, taken as having none
};

// Triangles of every face, polygons triangulated with their winding. Triangle::material holds the face's
// materialSlot + 1 (0 for none), for the caller to map once the materials are known. Triangle::uv holds
// the face's vt where every corner gives one (a face with some corners but not all is invalid OBJ and
// counts as having none). `noTexcoordLine` gets, per triangle, 0 if it has texture coordinates, else
// the line of its face.
std::vector<Triangle> buildTriangles(const ObjMesh& mesh, MeshRepairs* repairs,
                                     std::vector<int>* noTexcoordLine);

}  // namespace fp
