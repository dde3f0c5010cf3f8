#include "scene/light_selection.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "scene/punctual_light.h"

namespace fp {

float luminance(const glm::vec3& rgb) {
    return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

double punctualLightPower(const PunctualLight& light, float sceneRadius) {
    const double pi = 3.14159265358979324;
    double y = double(luminance(light.intensity));
    switch (light.type) {
        case PunctualLightType::Point:
            return 4.0 * pi * y;
        case PunctualLightType::Spot:
            return spotSolidAngle(light.innerConeAngle, light.outerConeAngle) * y;
        case PunctualLightType::Directional:
            return pi * double(sceneRadius) * double(sceneRadius) * y;
    }
    return 0.0;
}

double meanEmittedLuminance(const Scene& scene, const Material& m) {
    glm::vec3 emission = m.emission;
    if (m.emissionTexture >= 0 && size_t(m.emissionTexture) < scene.textures.size())
        emission *= meanLinearColor(scene.textures[size_t(m.emissionTexture)].image);
    double coverage = 1.0;
    if (m.alphaTexture < 0 && m.alphaMode == AlphaMode::Blend) coverage = double(m.alpha);
    if (m.alphaTexture < 0 && m.alphaMode == AlphaMode::Mask) coverage = m.alpha >= m.alphaCutoff ? 1.0 : 0.0;
    return double(luminance(emission)) * coverage;
}

EmitterPmfs emitterPmfs(const Scene& scene, const uint32_t* order, size_t count) {
    const size_t punctual = scene.punctualLights.size();
    std::vector<double> power(count + punctual, 0.0);
    std::vector<double> radiance(scene.materials.size(), 0.0);
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].isEmissive()) radiance[m] = meanEmittedLuminance(scene, scene.materials[m]);
    EmitterPmfs out;
    for (size_t i = 0; i < count; ++i) {
        const Triangle& t = scene.triangles[order[i]];
        if (radiance[t.material] > 0.0) power[i] = radiance[t.material] * double(t.area());
        out.totalPower += power[i];
    }
    if (punctual > 0) {
        bool directional =
            std::any_of(scene.punctualLights.begin(), scene.punctualLights.end(),
                        [](const PunctualLight& l) { return l.type == PunctualLightType::Directional; });
        float radius = directional ? directionalLightSphere(scene).radius : 0.0f;
        for (size_t k = 0; k < punctual; ++k) {
            power[count + k] = punctualLightPower(scene.punctualLights[k], radius) / 3.14159265358979324;
            out.totalPower += power[count + k];
        }
    }
    std::vector<float> pmf = lightPmfs(power, out.totalPower);
    out.punctualPmf.assign(pmf.begin() + std::ptrdiff_t(count), pmf.end());
    pmf.resize(count);
    out.pmf = std::move(pmf);
    return out;
}

std::vector<float> lightPmfs(const std::vector<double>& power, double totalPower) {
    constexpr double kGrid = 16777216.0;  // 2^24
    std::vector<float> pmf(power.size(), 0.0f);
    if (!(totalPower > 0.0)) return pmf;
    double running = 0.0, previous = 0.0;
    size_t last = 0;
    for (size_t i = 0; i < power.size(); ++i) {
        if (!(power[i] > 0.0)) continue;
        running += power[i];
        double cdf = std::min(1.0, std::round(running / totalPower * kGrid) / kGrid);
        pmf[i] = float(cdf - previous);
        previous = cdf;
        last = i;
    }
    // The last emitter closes the cdf at 1, so a uniform number in [0, 1) always finds one.
    pmf[last] += float(1.0 - previous);  // exact: both on the grid
    return pmf;
}

}  // namespace fp
