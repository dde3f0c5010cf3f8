// Test-only pass: runs the BSDF functions of common/bsdf.glsl one fragment at a time, so that the C++
// tests (tests/render/bsdf_*_test.cpp) can check them statistically, in the GLSL that renders, the way
// Mitsuba tests its BSDFs (Jakob et al., Mitsuba 3, src/python/python/chi2.py). Material 0 of
// uMaterials is the material under test.
//   uMode 0, SAMPLE: fragment (x, y) draws one bsdfSample for the fixed uWo and uEta with its own random
//                    numbers (rng.glsl, stream (uSeed, (x, y), 0)).
//                    out0 = (wi, pdf), out1 = (weight, flag): flag 0 failed, 1 non-delta, 2 delta.
//   uMode 1, EVAL:   wo and eta from uWoEta (xyz, w) and wi from uWi, per fragment.
//                    out0 = (bsdfEval, bsdfPdf), out1 = (isDeltaOnly, 0, 0, 0).
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/bsdf.glsl"

uniform int uMode;
uniform uint uSeed;
uniform vec3 uWo;
uniform float uEta;
uniform sampler2D uWoEta;
uniform sampler2D uWi;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    MaterialData m = fetchMaterial(0);
    if (uMode == 0) {
        rngInit(uSeed, uvec2(pixel), 0u);
        vec3 u = vec3(rand(), rand(), rand());
        BsdfSample s;
        if (bsdfSample(m, uWo, u, uEta, s)) {
            out0 = vec4(s.wi, s.pdf);
            out1 = vec4(s.weight, s.delta ? 2.0 : 1.0);
        } else {
            out0 = vec4(0.0);
            out1 = vec4(0.0);
        }
    } else {
        vec4 woEta = texelFetch(uWoEta, pixel, 0);
        vec3 wi = texelFetch(uWi, pixel, 0).xyz;
        out0 = vec4(bsdfEval(m, woEta.xyz, wi, woEta.w), bsdfPdf(m, woEta.xyz, wi, woEta.w));
        out1 = vec4(isDeltaOnly(m) ? 1.0 : 0.0, 0.0, 0.0, 0.0);
    }
}
