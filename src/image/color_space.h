#pragma once
// The colour spaces FLIP works in (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating
// Images", HPG): linear sRGB, CIE XYZ, the opponent space YCxCz and CIELAB with the Hunt adjustment.
// All use D65 white as the sRGB primaries define it: the XYZ of linear RGB (1, 1, 1).
#include <glm/glm.hpp>

namespace fp {

// The linear sRGB -> XYZ matrix of IEC 61966-2-1:1999 (the sRGB standard), and its inverse.
glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb);
glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz);

// The reference white: linearRgbToXyz((1, 1, 1)).
glm::dvec3 whiteXyz();

// YCxCz (Flohr, Kolpatzik, Balasubramanian, Carrara, Bouman and Allebach 1993, "Model-based color image
// quantization", SPIE 1913): CIELAB without the cube root, so linear in XYZ and safe to filter:
// Y = 116 y - 16, Cx = 500 (x - y), Cz = 200 (y - z), where x, y, z are X, Y, Z over the white's.
glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz);
glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz);

// CIE 1976 L*a*b* (CIE 15:2004): the cube root above (6/29)^3 and the linear segment below it.
glm::dvec3 xyzToLab(const glm::dvec3& xyz);
glm::dvec3 labToXyz(const glm::dvec3& lab);

// The Hunt adjustment of FLIP's colour pipeline: chroma shrinks with lightness, a* and b* scaled by
// 0.01 L* (dark colours look less colourful than bright ones of the same a*, b*: the Hunt effect).
glm::dvec3 huntAdjust(const glm::dvec3& lab);

// HyAB (Abasi, Amani Tehran and Fairchild 2020, "Distance metrics for very large color differences",
// Color Res. Appl. 45(2)): |dL| + sqrt(da^2 + db^2), a city-block lightness term and a Euclidean
// chroma term, which matches large differences better than the Euclidean distance in CIELAB.
double hyab(const glm::dvec3& labA, const glm::dvec3& labB);

}  // namespace fp
