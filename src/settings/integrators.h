#pragma once
// THE INTEGRATORS, one row each: what the rest of the program needs to know about an estimator. Adding
// one is its shader (glsl/integrators/<name>.glsl), an enumerator and a row of kIntegratorFacts
// (integrators.cpp); the command line, the scene file, the viewer and the study read the row.
#include <optional>

#include "settings/render_settings.h"

namespace fp {

struct IntegratorFacts {
    Integrator id;
    const char* name;     // --integrator NAME, the scene file's render.integrator, glsl/integrators/NAME.glsl
    const char* summary;  // one line for --help
    // Bounces the shader can trace; a longer --max-depth renders this depth, with a warning
    // (integratorDepth). 0: no cap.
    int depthCap;
    bool samplesLights;     // samples a point on an emitter at each vertex (next-event estimation)
    bool clampsIndirect;    // honours --clamp-indirect (bdpt's strategies share paths: no clamp)
    bool choosesCaustics;   // honours --caustics (a light pass for caustics seen directly)
    bool choosesLightTree;  // honours --light-selection (the others choose emitters by power)
    // The FLOP model of the study's roofline (study/flop_model.h): floating-point operations per surface
    // interaction, counted from the shader (the note says how), and the 2D sample pairs it draws there.
    double shadingFlops;
    const char* flopNote;
    double samplePairs;
};

const IntegratorFacts& integratorFacts(Integrator integrator);

struct Setting;
// Whether the integrator reads the setting (a row of settings/setting_table.h): nee alone chooses its
// caustics and light selection; bdpt has no clamp.
bool integratorHonours(Integrator integrator, const Setting& setting);

// The depth an integrator renders when asked for `maxDepth`: the lower of the two.
int integratorDepth(Integrator integrator, int maxDepth);

// "bdpt traces at most 12 bounces: --max-depth 64 renders depth 12", or nothing when `maxDepth` is
// within the integrator's cap.
std::optional<std::string> depthCapNote(Integrator integrator, int maxDepth);

}  // namespace fp
