#include "gpu/environment.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "gpu/layout.h"
#include "gpu/pack.h"
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

EnvironmentTextures::EnvironmentTextures(const PackedEnvironment& e) : size_(e.width, e.height) {
    const GLint maxSize = glInteger(GL_MAX_TEXTURE_SIZE), maxTexels = glInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
    if (e.width > maxSize || e.height > maxSize || e.cdf.size() > size_t(maxTexels))
        throw Error("environment map " + std::to_string(e.width) + "x" + std::to_string(e.height) +
                    " is larger than this GPU's textures (" + std::to_string(maxSize) + " per side)");
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kEnvironmentMapUnit));
    glGenTextures(1, &map_);
    glBindTexture(GL_TEXTURE_2D, map_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, e.width, e.height, 0, GL_RGBA, GL_FLOAT, e.texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenBuffers(1, &cdfBuffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, cdfBuffer_);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(e.cdf.size() * sizeof(float)), e.cdf.data(), GL_STATIC_DRAW);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kEnvironmentCdfUnit));
    glGenTextures(1, &cdfTexture_);
    glBindTexture(GL_TEXTURE_BUFFER, cdfTexture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, cdfBuffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

EnvironmentTextures::~EnvironmentTextures() {
    glDeleteTextures(1, &map_);
    glDeleteTextures(1, &cdfTexture_);
    glDeleteBuffers(1, &cdfBuffer_);
}

void EnvironmentTextures::bind(SceneReads reads) const {
    bindSceneTexture(reads, layout::kEnvironmentMapUnit, GL_TEXTURE_2D, map_, GL_RGBA32F);
    bindSceneTexture(reads, layout::kEnvironmentCdfUnit, GL_TEXTURE_BUFFER, cdfTexture_, GL_R32F);
}

}  // namespace fp
