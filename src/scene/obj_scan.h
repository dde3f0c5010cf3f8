#pragma once
// The strict first pass over OBJ text. tinyobjloader is lenient where we must not be: it reads "abc",
// "nan" and "inf" as 0, passes out-of-range indices and relative indices before the first vertex
// through, and keeps no line numbers. This pass checks every v/vn/vt/f statement, rejects what is
// malformed with its line number, and hands tinyobjloader a normalized copy that it can only read one
// way.
#include <string>
#include <string_view>
#include <vector>

#include "scene/repair_tally.h"

namespace fp {

// One `mtllib` statement: usually one file name, but it may list several, or be one name with blanks.
struct MtlLibraryRef {
    int line;
    std::string names;  // the rest of the statement, trimmed
};

struct ObjScan {
    // For tinyobjloader: one statement per '\n'-terminated line, only v, vn, vt, f and usemtl statements
    // (everything else blanked so line numbers stay aligned), spelled canonically with single spaces,
    // vt as "vt u v", face indices made absolute (1-based) as v, v/vt, v//vn or v/vt/vn.
    std::string text;
    // Per `v` and `vn` statement: whether x, y and z are finite as floats (tinyobjloader reads nan and
    // inf as 0, which would turn "vn nan 0 1" into a plausible normal).
    std::vector<bool> vertexFinite;
    std::vector<bool> normalFinite;
    std::vector<bool> texcoordFinite;  // per `vt`: whether u and v are finite as floats
    // Source line of every face with at least 3 vertices, in file order (tinyobjloader reports faces in
    // this order, so the k-th face it reports came from faceLines[k]).
    std::vector<int> faceLines;
    size_t cornerCount = 0;  // over those faces: what the mesh's corner array will hold
    std::vector<MtlLibraryRef> materialLibraries;
    RepairTally shortFaces;  // faces with fewer than 3 vertices, left out of `text`
};

// Throws fp::Error "<name>:<line>: ..." on malformed numbers or indices (zero, out of range, relative
// before the first vertex).
ObjScan scanObj(std::string_view text, const std::string& name);

}  // namespace fp
