// Test-only pass for tests/render/rng_test.cpp. Mode 0: fragment (x, y) writes the first eight numbers of
// the random stream of sample uSample at pixel (x, y). Mode 1: fragment i (row by row) writes the first
// two 2D points (dimension pairs 0 and 1) of sample i at pixel uPixel, to see one pixel's samples. Modes
// 2 and 3 are modes 1 and 0 with pair 0 drawn by rand2Coherent and pair 1 by rand2 (mode 3: into out0).
#include "common/rng.glsl"

uniform uint uSeed;
uniform uint uSample;
uniform int uMode;
uniform ivec2 uPixel;
uniform int uWidth;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;

void main() {
    if (uMode == 3) {
        rngInit(uSeed, uvec2(gl_FragCoord.xy), uSample);
        out0 = vec4(rand2Coherent(), rand2());
        out1 = vec4(0.0);
    } else if (uMode == 0) {
        rngInit(uSeed, uvec2(gl_FragCoord.xy), uSample);
        out0 = vec4(rand(), rand(), rand(), rand());
        out1 = vec4(rand(), rand(), rand(), rand());
    } else {
        ivec2 f = ivec2(gl_FragCoord.xy);
        rngInit(uSeed, uvec2(uPixel), uint(f.y * uWidth + f.x));
        vec2 first = uMode == 2 ? rand2Coherent() : rand2();
        out0 = vec4(first, rand2());
        out1 = vec4(0.0);
    }
}
