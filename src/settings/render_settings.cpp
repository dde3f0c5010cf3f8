#include "settings/render_settings.h"

#include "core/error.h"
#include "core/text.h"
#include "settings/integrators.h"

namespace fp {

Integrator parseIntegrator(const std::string& name) {
    return parseName(name, kAllIntegrators, integratorName, "integrator");
}

const char* integratorName(Integrator integrator) {
    return integratorFacts(integrator).name;
}

Sampler parseSampler(const std::string& name) {
    return parseName(name, kAllSamplers, samplerName, "sampler");
}

const char* samplerName(Sampler sampler) {
    static constexpr const char* kNames[] = {"independent", "sobol"};  // in enum order
    return nameOf(sampler, kNames);
}

LightSampling parseLightSampling(const std::string& name) {
    return parseName(name, kAllLightSamplings, lightSamplingName, "light sampling");
}

const char* lightSamplingName(LightSampling sampling) {
    static constexpr const char* kNames[] = {"auto", "area", "solid-angle"};  // in enum order
    return nameOf(sampling, kNames);
}

LightSelection parseLightSelection(const std::string& name) {
    return parseName(name, kAllLightSelections, lightSelectionName, "light selection");
}

const char* lightSelectionName(LightSelection selection) {
    static constexpr const char* kNames[] = {"auto", "power", "tree"};  // in enum order
    return nameOf(selection, kNames);
}

Caustics parseCaustics(const std::string& name) {
    return parseName(name, kAllCaustics, causticsName, "caustics");
}

const char* causticsName(Caustics caustics) {
    static constexpr const char* kNames[] = {"auto", "path", "light"};  // in enum order
    return nameOf(caustics, kNames);
}

View parseView(const std::string& name) {
    return parseName(name, kAllViews, viewName, "view");
}

const char* viewName(View view) {
    static constexpr const char* kNames[] = {"radiance", "depth", "normal",    "albedo",
                                             "bounces",  "nodes", "triangles", "cost"};  // in enum order
    return nameOf(view, kNames);
}

std::string samplesPerPassName(int samplesPerPass) {
    return samplesPerPass == RenderSettings::kAutoSamplesPerPass ? "auto" : std::to_string(samplesPerPass);
}

}  // namespace fp
