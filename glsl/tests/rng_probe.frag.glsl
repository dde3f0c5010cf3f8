// Test-only pass: fragment (x, y) writes the first eight numbers of the random stream of sample uSample
// at pixel (x, y) (common/rng.glsl), for tests/render/rng_test.cpp.
#include "common/rng.glsl"

uniform uint uSeed;
uniform uint uSample;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
    rngInit(uSeed, uvec2(gl_FragCoord.xy), uSample);
    out0 = vec4(rand(), rand(), rand(), rand());
    out1 = vec4(rand(), rand(), rand(), rand());
}
