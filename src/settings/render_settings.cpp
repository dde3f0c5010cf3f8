#include "settings/render_settings.h"

#include "core/error.h"

namespace fp {

Integrator parseIntegrator(const std::string& name) {
    for (Integrator i : kAllIntegrators)
        if (name == integratorName(i)) return i;
    throw Error("unknown integrator '" + name + "' (choose naive, bsdf, nee or bdpt)");
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
    for (Sampler s : kAllSamplers)
        if (name == samplerName(s)) return s;
    throw Error("unknown sampler '" + name + "' (choose sobol or independent)");
}

const char* samplerName(Sampler sampler) {
    return sampler == Sampler::Sobol ? "sobol" : "independent";
}

LightSampling parseLightSampling(const std::string& name) {
    for (LightSampling l : kAllLightSamplings)
        if (name == lightSamplingName(l)) return l;
    throw Error("unknown light sampling '" + name + "' (choose auto, area or solid-angle)");
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
    for (View v : kAllViews)
        if (name == viewName(v)) return v;
    throw Error("unknown view '" + name +
                "' (choose radiance, depth, normal, albedo, bounces, nodes, triangles or cost)");
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
