#include "gpu/layout.h"

#include <string>

namespace fp::layout {

ShaderDefines layoutDefines() {
    auto s = [](int v) { return std::to_string(v); };
    return {{"TRIANGLE_TEXELS", s(kTriangleTexels)},      {"NORMAL_TEXELS", s(kNormalTexels)},
            {"NODE_BOUNDS_TEXELS", s(kNodeBoundsTexels)}, {"MATERIAL_TEXELS", s(kMaterialTexels)},
            {"TRIANGLES_UNIT", s(kTrianglesUnit)},        {"NORMALS_UNIT", s(kNormalsUnit)},
            {"NODE_BOUNDS_UNIT", s(kNodeBoundsUnit)},     {"NODE_LINKS_UNIT", s(kNodeLinksUnit)},
            {"MATERIALS_UNIT", s(kMaterialsUnit)},        {"LIGHTS_UNIT", s(kLightsUnit)},
            {"TEXCOORD_TEXELS", s(kTexcoordTexels)}};
}

}  // namespace fp::layout
