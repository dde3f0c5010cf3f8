#include "image/color_space.h"

#include <cmath>

namespace fp {

namespace {

// IEC 61966-2-1:1999 section 5.2, RGB (linear, D65) to XYZ. glm matrices are column-major, so each
// glm::dvec3 below is a column: the XYZ of one primary at full intensity.
const glm::dmat3 kRgbToXyz(glm::dvec3(0.4124, 0.2126, 0.0193), glm::dvec3(0.3576, 0.7152, 0.1192),
                           glm::dvec3(0.1805, 0.0722, 0.9505));
const glm::dmat3 kXyzToRgb = glm::inverse(kRgbToXyz);
const glm::dvec3 kWhite = kRgbToXyz * glm::dvec3(1.0);

// The CIELAB companding function f(t): a cube root above (6/29)^3, a line of the same value and slope
// below it (CIE 15:2004, the CIE 1976 L*a*b* space).
double labF(double t) {
    const double delta = 6.0 / 29.0;
    if (t > delta * delta * delta) return std::cbrt(t);
    return t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// Its inverse: the cube above 6/29, the line below.
double labFInverse(double f) {
    const double delta = 6.0 / 29.0;
    if (f > delta) return f * f * f;
    return 3.0 * delta * delta * (f - 4.0 / 29.0);
}

}  // namespace

glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb) {
    return kRgbToXyz * rgb;
}

glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz) {
    return kXyzToRgb * xyz;
}

glm::dvec3 whiteXyz() {
    return kWhite;
}

glm::dvec3 xyzToYcxcz(const glm::dvec3& xyz) {
    const glm::dvec3 n = xyz / kWhite;
    return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

glm::dvec3 ycxczToXyz(const glm::dvec3& ycxcz) {
    const double y = (ycxcz.x + 16.0) / 116.0;
    return glm::dvec3(y + ycxcz.y / 500.0, y, y - ycxcz.z / 200.0) * kWhite;
}

glm::dvec3 xyzToLab(const glm::dvec3& xyz) {
    const glm::dvec3 n = xyz / kWhite;
    const double fx = labF(n.x), fy = labF(n.y), fz = labF(n.z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 labToXyz(const glm::dvec3& lab) {
    const double fy = (lab.x + 16.0) / 116.0;
    return glm::dvec3(labFInverse(fy + lab.y / 500.0), labFInverse(fy), labFInverse(fy - lab.z / 200.0)) *
           kWhite;
}

glm::dvec3 huntAdjust(const glm::dvec3& lab) {
    return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z};
}

double hyab(const glm::dvec3& labA, const glm::dvec3& labB) {
    const glm::dvec3 d = labA - labB;
    return std::abs(d.x) + std::sqrt(d.y * d.y + d.z * d.z);
}

}  // namespace fp
