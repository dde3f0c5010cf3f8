#include "pack/environment.h"

#include <cmath>

#include "scene/light_selection.h"

namespace fp {

PackedEnvironment packEnvironment(const Environment& environment) {
    PackedEnvironment out;
    const Image& map = environment.map;
    out.width = map.width;
    out.height = map.height;
    out.texels.reserve(map.pixels.size());
    for (const glm::vec3& p : map.pixels) out.texels.emplace_back(p * environment.intensity, 0.0f);

    const int w = map.width, h = map.height;
    out.cdf.assign(size_t(h) + size_t(w) * size_t(h), 0.0f);
    std::vector<double> rowSums(size_t(h), 0.0);
    for (int y = 0; y < h; ++y) {
        double sinTheta = std::sin(3.14159265358979 * (y + 0.5) / h);
        double sum = 0.0;
        float* row = &out.cdf[size_t(h) + size_t(y) * size_t(w)];
        for (int x = 0; x < w; ++x) {
            sum += double(luminance(glm::vec3(out.texels[size_t(y) * size_t(w) + size_t(x)]))) * sinTheta;
            row[x] = float(sum);
        }
        // Normalise the row; a black row is never chosen, but give it a valid (uniform) CDF anyway.
        for (int x = 0; x < w; ++x) row[x] = sum > 0.0 ? float(row[x] / sum) : float(x + 1) / float(w);
        row[w - 1] = 1.0f;
        rowSums[size_t(y)] = sum;
        out.totalWeight += sum;
    }
    double running = 0.0;
    for (int y = 0; y < h; ++y) {
        running += rowSums[size_t(y)];
        out.cdf[size_t(y)] =
            out.totalWeight > 0.0 ? float(running / out.totalWeight) : float(y + 1) / float(h);
    }
    if (h > 0) out.cdf[size_t(h) - 1] = 1.0f;
    return out;
}

}  // namespace fp
