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

}  // namespace fp
