#include "settings/render_settings.h"

#include "core/error.h"
#include "core/text.h"

namespace fp {

Integrator parseIntegrator(const std::string& name) {
    return parseName(name, kAllIntegrators, integratorName, "integrator");
}

const char* integratorName(Integrator integrator) {
    switch (integrator) {
        case Integrator::Naive:
            return "naive";
        case Integrator::Bsdf:
            return "bsdf";
        case Integrator::Nee:
            return "nee";
        case Integrator::Bdpt:
            return "bdpt";
    }
    return "?";
}

Sampler parseSampler(const std::string& name) {
    return parseName(name, kAllSamplers, samplerName, "sampler");
}

const char* samplerName(Sampler sampler) {
    return sampler == Sampler::Sobol ? "sobol" : "independent";
}

LightSampling parseLightSampling(const std::string& name) {
    return parseName(name, kAllLightSamplings, lightSamplingName, "light sampling");
}

const char* lightSamplingName(LightSampling sampling) {
    switch (sampling) {
        case LightSampling::Area:
            return "area";
        case LightSampling::SolidAngle:
            return "solid-angle";
        default:
            return "auto";
    }
}

View parseView(const std::string& name) {
    return parseName(name, kAllViews, viewName, "view");
}

const char* viewName(View view) {
    switch (view) {
        case View::Radiance:
            return "radiance";
        case View::Depth:
            return "depth";
        case View::Normal:
            return "normal";
        case View::Albedo:
            return "albedo";
        case View::Bounces:
            return "bounces";
        case View::Nodes:
            return "nodes";
        case View::Triangles:
            return "triangles";
        case View::Cost:
            return "cost";
    }
    return "?";
}

}  // namespace fp
