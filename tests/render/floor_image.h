#pragma once
// What a pinhole camera looking down at the floor plane y = 0 should see, pixel by pixel, when the
// floor's radiance has a closed form: the camera rays as glsl/common/camera.glsl builds them (in
// double), the floor point each one hits, and each pixel's expected mean (the closed form averaged over
// the pixel's footprint, as the shader's box filter averages it).
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp::test {

// The camera ray through continuous pixel position (x, y) (y up, as gl_FragCoord) of a size x size
// image, as glsl/common/camera.glsl builds it, in double.
inline glm::dvec3 cameraDirection(const Camera& c, int size, double x, double y) {
    constexpr double pi = 3.14159265358979324;
    glm::dvec3 forward = glm::normalize(glm::dvec3(c.target) - glm::dvec3(c.eye));
    glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(c.up)));
    glm::dvec3 up = glm::cross(right, forward);
    double tanHalf = std::tan(0.5 * double(c.fovY) * pi / 180.0);
    double nx = 2.0 * x / size - 1.0, ny = 2.0 * y / size - 1.0;
    return glm::normalize(forward + nx * tanHalf * right + ny * tanHalf * up);
}

// The floor point the camera ray through (x, y) hits (the camera looks down at it).
inline glm::dvec3 floorPoint(const Camera& c, int size, double x, double y) {
    glm::dvec3 d = cameraDirection(c, size, x, y), eye(c.eye);
    return eye + d * (-eye.y / d.y);
}

// Each pixel's expected mean, image rows top first (as Accumulation stores them): `value` at continuous
// pixel positions (x, y) (y up) averaged over the pixel's area (the shader's box filter), by the
// midpoint rule on a 16 x 16 grid.
inline std::vector<glm::dvec3> pixelAverages(int size,
                                             const std::function<glm::dvec3(double x, double y)>& value) {
    constexpr int n = 16;
    std::vector<glm::dvec3> image(size_t(size) * size_t(size));
    for (int row = 0; row < size; ++row)
        for (int x = 0; x < size; ++x) {
            int glY = size - 1 - row;
            glm::dvec3 sum(0.0);
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) sum += value(x + (i + 0.5) / n, glY + (j + 0.5) / n);
            image[size_t(row) * size_t(size) + size_t(x)] = sum / double(n * n);
        }
    return image;
}

// The same of `radiance(floor point)`.
inline std::vector<glm::dvec3> expectedFloorImage(
    const Camera& c, int size, const std::function<glm::dvec3(const glm::dvec3&)>& radiance) {
    return pixelAverages(size, [&](double x, double y) { return radiance(floorPoint(c, size, x, y)); });
}

}  // namespace fp::test
