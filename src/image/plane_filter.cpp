#include "image/plane_filter.h"

#include <algorithm>

namespace fp {

namespace {

// One pass along x (alongRows) or y, with clamp-to-edge indices.
Plane filterPass(const Plane& in, const std::vector<double>& kernel, bool alongRows) {
    Plane out(in.width, in.height);
    const int r = int(kernel.size() / 2);
    const int last = (alongRows ? in.width : in.height) - 1;
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            double sum = 0.0;
            for (int i = 0; i < int(kernel.size()); ++i) {
                const int along = std::clamp((alongRows ? x : y) + i - r, 0, last);
                sum += kernel[size_t(i)] * (alongRows ? in.at(along, y) : in.at(x, along));
            }
            out.at(x, y) = sum;
        }
    }
    return out;
}

}  // namespace

Plane filterSeparable(const Plane& in, const std::vector<double>& horizontal,
                      const std::vector<double>& vertical) {
    return filterPass(filterPass(in, horizontal, true), vertical, false);
}

}  // namespace fp
