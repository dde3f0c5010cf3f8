#include "image/plane_filter.h"

#include <algorithm>

namespace fp {

namespace {

// Along x: each row is copied once into a buffer padded by r copies of its end values (clamp to
// edge), so the inner loop is a plain dot product.
Plane filterRows(const Plane& in, const std::vector<double>& kernel) {
    Plane out(in.width, in.height);
    const int r = int(kernel.size() / 2);
    std::vector<double> padded(size_t(in.width + 2 * r));
    for (int y = 0; y < in.height; ++y) {
        for (int i = 0; i < in.width + 2 * r; ++i)
            padded[size_t(i)] = in.at(std::clamp(i - r, 0, in.width - 1), y);
        for (int x = 0; x < in.width; ++x) {
            double sum = 0.0;
            for (size_t k = 0; k < kernel.size(); ++k) sum += kernel[k] * padded[size_t(x) + k];
            out.at(x, y) = sum;
        }
    }
    return out;
}

// Along y: whole rows are weighted and added (the clamped row index repeats the edge rows), which walks
// memory in order; each pixel still sums its terms in kernel order.
Plane filterColumns(const Plane& in, const std::vector<double>& kernel) {
    Plane out(in.width, in.height);
    const int r = int(kernel.size() / 2);
    for (int y = 0; y < in.height; ++y) {
        double* dst = &out.at(0, y);
        for (size_t k = 0; k < kernel.size(); ++k) {
            const int row = std::clamp(y + int(k) - r, 0, in.height - 1);
            const double* src = in.values.data() + size_t(row) * size_t(in.width);
            for (int x = 0; x < in.width; ++x) dst[x] += kernel[k] * src[x];
        }
    }
    return out;
}

}  // namespace

Plane filterSeparable(const Plane& in, const std::vector<double>& horizontal,
                      const std::vector<double>& vertical) {
    return filterColumns(filterRows(in, horizontal), vertical);
}

}  // namespace fp
