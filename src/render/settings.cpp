#include "render/settings.h"

#include "core/error.h"

namespace fp {

Integrator parseIntegrator(const std::string& name) {
    if (name == "naive") return Integrator::Naive;
    if (name == "bsdf") return Integrator::Bsdf;
    if (name == "nee") return Integrator::Nee;
    throw Error("unknown integrator '" + name + "' (choose naive, bsdf or nee)");
}

const char* integratorName(Integrator integrator) {
    switch (integrator) {
        case Integrator::Naive:
            return "naive";
        case Integrator::Bsdf:
            return "bsdf";
        case Integrator::Nee:
            return "nee";
    }
    return "?";
}

View parseView(const std::string& name) {
    for (View v : {View::Radiance, View::Depth, View::Normal, View::Albedo})
        if (name == viewName(v)) return v;
    throw Error("unknown view '" + name + "' (choose radiance, depth, normal or albedo)");
}

const char* viewName(View view) {
    switch (view) {
        case View::Radiance: return "radiance";
        case View::Depth: return "depth";
        case View::Normal: return "normal";
        case View::Albedo: return "albedo";
    }
    return "?";
}

}  // namespace fp
