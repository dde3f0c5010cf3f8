#pragma once
// One channel of an image as doubles, and separable filtering of it: what FLIP's spatial filters need.
#include <cstddef>
#include <vector>

namespace fp {

struct Plane {
    int width = 0, height = 0;
    std::vector<double> values;  // row-major, row 0 at the top, as in Image

    Plane() = default;
    Plane(int w, int h) : width(w), height(h), values(size_t(w) * size_t(h), 0.0) {}
    double& at(int x, int y) { return values[size_t(y) * size_t(width) + size_t(x)]; }
    double at(int x, int y) const { return values[size_t(y) * size_t(width) + size_t(x)]; }
};

// The plane filtered along rows with `horizontal`, then along columns with `vertical`: the 2D kernel
// k(i, j) = horizontal[i] * vertical[j]. Kernels have odd length 2r + 1 and weight i applies to the
// pixel i - r away (a correlation, as filters are usually stated). Outside the plane the nearest edge
// pixel is repeated, so a flat plane stays flat under any kernel that sums to 1.
Plane filterSeparable(const Plane& in, const std::vector<double>& horizontal,
                      const std::vector<double>& vertical);

}  // namespace fp
