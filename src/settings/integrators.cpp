#include "settings/integrators.h"

#include <iterator>
#include <string>

#include "settings/setting_table.h"

namespace fp {

namespace {

// In enum order (static_assert below). The FLOP counts are read off the shaders by hand: see each note.
constexpr IntegratorFacts kIntegratorFacts[] = {
    {Integrator::Naive, "naive", "uniform hemisphere sampling, the textbook's first estimator", 0, false,
     true, false, false, 165.0, "surfaceAt 77, emission 6, uniform hemisphere 43, weight, roulette, spawn",
     1.0},
    {Integrator::Bsdf, "bsdf", "BSDF sampling; lights are found only by chance", 0, false, true, false, false,
     163.0, "surfaceAt 77, emission 6, cosine sample, frames, roulette, spawn", 2.0},
    {Integrator::Nee, "nee", "next-event estimation: light sampling with MIS", 0, true, true, true, true,
     298.0, "bsdf's 163 + light sample 68, BSDF eval + pdf, MIS, shadow ray", 4.0},
    // BDPT_MAX_DEPTH (glsl/integrators/bdpt_subpaths.glsl): the camera subpath's vertices are stored,
    // z0 .. z_{D+1}, so the cap sizes the shader's arrays.
    {Integrator::Bdpt, "bdpt", "bidirectional path tracing (Veach 1997)", 12, true, false, false, false,
     298.0, "as nee (lower bound: join MIS weights not counted)", 4.0},
};

constexpr bool inEnumOrder() {
    for (size_t i = 0; i < std::size(kIntegratorFacts); ++i)
        if (size_t(kIntegratorFacts[i].id) != i) return false;
    return std::size(kIntegratorFacts) == std::size(kAllIntegrators);
}
static_assert(inEnumOrder(), "one row per Integrator, in enum order");

}  // namespace

const IntegratorFacts& integratorFacts(Integrator integrator) {
    return kIntegratorFacts[size_t(integrator)];
}

bool integratorHonours(Integrator integrator, const Setting& setting) {
    const IntegratorFacts& facts = integratorFacts(integrator);
    const std::string name = setting.name;
    if (name == "caustics") return facts.choosesCaustics;
    if (name == "light_selection") return facts.choosesLightTree;
    if (name == "clamp_indirect") return facts.clampsIndirect;
    return true;
}

int integratorDepth(Integrator integrator, int maxDepth) {
    const int cap = integratorFacts(integrator).depthCap;
    return cap > 0 && maxDepth > cap ? cap : maxDepth;
}

std::optional<std::string> depthCapNote(Integrator integrator, int maxDepth) {
    const IntegratorFacts& facts = integratorFacts(integrator);
    if (integratorDepth(integrator, maxDepth) == maxDepth) return std::nullopt;
    return std::string(facts.name) + " traces at most " + std::to_string(facts.depthCap) +
           " bounces: --max-depth " + std::to_string(maxDepth) + " renders depth " +
           std::to_string(facts.depthCap);
}

}  // namespace fp
