#pragma once
// Variants of the production shaders that the tests need and the program never renders: each isolates
// one strategy or undoes one choice, by editing a copy of the test shaders (test_shaders.h,
// testShadersEdited). The edits name the lines they change, so a change to those lines fails loudly
// (fp::Error) instead of testing the unedited shaders.
//
// What each one lets the tests see (tried on copies through FP_RENDER_TEST_SHADERS): light tracing's
// weight times 0.9 (passes/light_trace.frag.glsl) fails Bdpt.LightTracingAloneConvergesToNee,
// DepthOfField.LightTracingAloneConvergesToNeeThroughALens and the point, spot and directional light
// tests; the light pass leaving out the light caustics send on (causticStrategy, s > 3) fails
// Caustics.LightPassFindsTheLightCausticsSendOnAsCameraPathsDo (light 0x the camera paths) and the glossy
// metal's restricted comparison (0.60x) while its whole image passes (0.99x). With the variants made
// no-ops, Bdpt.LightTracingAloneConvergesToNee and SobolSampler.JitterAndLightPointAreStratifiedTogether
// fail.
#include <string>

#include "test_shaders.h"

namespace fp::test {

// bdpt by light tracing alone: every MIS weight 0 but that of strategy t = 1, the light subpath joined
// to the camera (bdpt_test.cpp, punctual_light_test.cpp, depth_of_field_test.cpp).
inline ShaderLibrary lightTracingOnlyShaders() {
    return testShadersEdited(
        "light_tracing_only",
        {{"integrators/bdpt_subpaths.glsl", "bool deltaLight) {\n",
          "bool deltaLight) {\n    return t == 1 ? 1.0 : 0.0;  // light tracing alone\n"}});
}

// nee's caustic paths alone, those the light pass sums (--caustics light) or, with --caustics path, the
// camera paths that find the same light, with at least `smoothVertices` smooth vertices (2: the light
// that caustics send on): both passes sum nothing else (caustics_test.cpp).
inline ShaderLibrary lightPassPathsOnlyShaders(int smoothVertices) {
    const std::string n = std::to_string(smoothVertices);
    return testShadersEdited(
        "light_pass_paths_only_" + n,
        {// the camera pass: emitters met, and light samples (x_{m+1} the light, at depth + 1)
         {"integrators/nee.glsl", "    if (Le != vec3(0.0))\n",
          "    if (!lightPassPath || p.causticSmooth < " + n +
              ") Le = vec3(0.0);\n    if (Le != vec3(0.0))\n"},
         {"integrators/nee.glsl", "    if (lightSample) {\n",
          "    lightSample = lightSample && lightPassSample && p.causticSmooth >= " + n +
              ";\n    if (lightSample) {\n"},
         // the light pass: smooth vertices counted with the receiver y_{s-1}
         {"integrators/bdpt_subpaths.glsl", "    return smoothSamples < CAUSTIC_SMOOTH_BOUNCES;\n",
          "    if (smoothSamples + 1 < " + n +
              ") return false;\n    return smoothSamples < CAUSTIC_SMOOTH_BOUNCES;\n"}});
}

// The Sobol sampler with every pair padded by its own shuffle, none of them joint (rng.glsl,
// kJointPairs): what sobol_sampler_test.cpp compares the joint pairs with.
inline ShaderLibrary paddedSobolPairsShaders() {
    return testShadersEdited("padded_sobol_pairs", {{"common/rng.glsl", "const uint kJointPairs = 2u;",
                                                     "const uint kJointPairs = 0u;"}});
}

// Paths the roulette never stops (surface.glsl, kRouletteDepth beyond any depth): unbiased whatever the
// roulette's code does, the reference of roulette_bias_test.cpp where no closed form exists.
inline ShaderLibrary noRouletteShaders() {
    return testShadersEdited("no_roulette", {{"common/surface.glsl", "const int kRouletteDepth = 3;",
                                              "const int kRouletteDepth = 1 << 30;"}});
}

}  // namespace fp::test
