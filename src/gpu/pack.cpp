#include "gpu/pack.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bvh/wide_bvh.h"
#include "core/error.h"
#include "gpu/layout.h"
#include "scene/spectrum.h"

namespace fp {

float luminance(const glm::vec3& rgb) {
    return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

size_t PackedScene::bytes() const {
    return sizeof(glm::vec4) * (triangles.size() + normals.size() + materials.size() + lights.size()) +
           sizeof(glm::uvec4) * nodes.size() + textureBytes();
}

size_t PackedScene::textureBytes() const {
    return sizeof(glm::vec2) * texcoords.size() + textureTexels.size() +
           sizeof(glm::ivec4) * textureTable.size();
}

size_t PackedScene::geometryBytes() const {
    return sizeof(glm::vec4) * triangles.size() + sizeof(glm::uvec4) * nodes.size();
}

namespace {

// Texture coordinates in leaf order, and every texture's texels with its table entry (gpu/layout.h).
void packTextures(const Scene& scene, const Bvh& bvh, PackedScene* out) {
    out->texcoords.reserve(bvh.primIndex.size() * layout::kTexcoordTexels);
    for (uint32_t prim : bvh.primIndex)
        for (const glm::vec2& uv : scene.triangles[prim].uv) out->texcoords.push_back(uv);
    size_t texels = 0;
    for (const Texture& t : scene.textures) texels += size_t(t.image.width) * size_t(t.image.height);
    // The table holds offsets as signed 32-bit integers.
    if (texels >= (size_t(1) << 31))
        throw Error(scene.source + ": the textures have " + std::to_string(texels) +
                    " texels in all; the GPU layout addresses at most 2^31 - 1");
    out->textureTexels.reserve(texels * 4);
    for (const Texture& t : scene.textures) {
        if (t.image.texels.size() != size_t(t.image.width) * size_t(t.image.height) * 4 || t.image.width <= 0)
            throw Error("internal: texture '" + t.name + "' has the wrong number of texels");
        out->textureTable.emplace_back(int(out->textureTexels.size() / 4), t.image.width, t.image.height, 0);
        out->textureTexels.insert(out->textureTexels.end(), t.image.texels.begin(), t.image.texels.end());
    }
}

}  // namespace

std::vector<float> lightPmfs(const std::vector<double>& power, double totalPower) {
    // The shader picks the first emitter whose cdf exceeds u = k / 2^24 (rand() in glsl/common/rng.glsl),
    // so emitter i is picked with probability (cdf_i - cdf_{i-1}) exactly when every cdf entry lies on
    // that grid. The cdf is summed in double, rounded to the grid, and each pmf is the difference of two
    // rounded entries: the number the pdf uses is then the probability of the pick, for any count of
    // emitters (a running float sum drifts from the stored pmfs by far more than a small emitter's
    // share once there are ~1e5 of them). An emitter whose share rounds to 0 is never picked and has
    // density 0, which BSDF sampling then covers in full (its MIS weight is 1): still unbiased.
    constexpr double kGrid = 16777216.0;  // 2^24
    std::vector<float> pmf(power.size(), 0.0f);
    if (!(totalPower > 0.0)) return pmf;
    double running = 0.0, previous = 0.0;
    for (size_t i = 0; i < power.size(); ++i) {
        if (power[i] <= 0.0) continue;
        running += power[i];
        double cdf = std::min(1.0, std::round(running / totalPower * kGrid) / kGrid);
        pmf[i] = float(cdf - previous);
        previous = cdf;
    }
    // The last emitter closes the cdf at 1, so a uniform number in [0, 1) always finds one.
    for (size_t i = power.size(); i-- > 0;)
        if (power[i] > 0.0) {
            pmf[i] = float(1.0 - (previous - double(pmf[i])));
            break;
        }
    return pmf;
}

PackedScene packScene(const Scene& scene, const Bvh& bvh) {
    PackedScene out;
    const size_t n = bvh.primIndex.size();
    if (n != scene.triangles.size() || n == 0 || bvh.nodes.empty())
        throw Error("internal: BVH does not match the scene's " + std::to_string(scene.triangles.size()) +
                    " triangles");
    if (n >= layout::kMaxFloatIndex || scene.materials.size() >= layout::kMaxFloatIndex)
        throw Error(scene.source + ": " + std::to_string(n) + " triangles and " +
                    std::to_string(scene.materials.size()) + " materials; the GPU layout addresses at most " +
                    std::to_string(layout::kMaxFloatIndex - 1) + " of each");
    out.triangleCount = uint32_t(n);

    // Emitters and their selection probabilities, proportional to emitted power (luminance * area).
    std::vector<double> power(n, 0.0);
    double totalPower = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const Triangle& t = scene.triangles[bvh.primIndex[i]];
        const Material& m = scene.materials[t.material];
        if (m.isEmissive()) power[i] = double(luminance(m.emission)) * double(t.area());
        totalPower += power[i];
    }
    out.totalLightPower = float(totalPower);
    std::vector<float> pmf = lightPmfs(power, totalPower);

    out.triangles.reserve(n * layout::kTriangleTexels);
    out.normals.reserve(n * layout::kNormalTexels);
    float cdf = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        const Triangle& t = scene.triangles[bvh.primIndex[i]];
        out.triangles.emplace_back(t.p[0], float(t.material));
        out.triangles.emplace_back(t.p[1] - t.p[0], pmf[i]);
        out.triangles.emplace_back(t.p[2] - t.p[0], 0.0f);
        for (const glm::vec3& normal : t.n) out.normals.emplace_back(normal, 0.0f);
        if (pmf[i] > 0.0f) {
            cdf += pmf[i];  // exact: every pmf and partial sum is a multiple of 2^-24 in [0, 1]
            out.lights.emplace_back(float(i), cdf, pmf[i], t.area());
        }
    }
    out.lightCount = uint32_t(out.lights.size());

    bool textured = false;
    for (const Material& m : scene.materials) {
        if (m.diffuseTexture >= int32_t(scene.textures.size()))
            throw Error("internal: material '" + m.name + "' names texture " +
                        std::to_string(m.diffuseTexture) + " of " + std::to_string(scene.textures.size()));
        textured = textured || m.diffuseTexture >= 0;
        out.materials.emplace_back(m.diffuse, float(m.type));
        out.materials.emplace_back(m.emission, m.roughness);
        out.materials.emplace_back(m.specular, m.ior);
        out.materials.emplace_back(m.transmission, spectrum::cauchyFromAbbe(m.ior, m.abbeNumber).y);
        out.materials.emplace_back(float(std::max(m.diffuseTexture, -1)), 0.0f, 0.0f, 0.0f);
    }
    if (textured) packTextures(scene, bvh, &out);

    WideBvh wide = collapseToWide(bvh);
    out.nodeCount = uint32_t(wide.nodes.size());
    out.bvhDepth = wide.depth;
    out.nodes.resize(size_t(out.nodeCount) * layout::kNodeTexels);
    for (uint32_t i = 0; i < out.nodeCount; ++i) {
        layout::QuantisedNode q = layout::quantiseNode(wide.nodes[i]);
        std::copy(q.begin(), q.end(), &out.nodes[size_t(i) * layout::kNodeTexels]);
    }
    return out;
}

}  // namespace fp
