// Test-only pass for tests/render/depth_of_field_test.cpp: fragment (x, y) starts sample uSample of pixel
// (x, y) as the trace pass does (rngInit, then the pixel jitter from pair 0) and writes what primaryRay
// (common/camera.glsl) makes of it: out0 = (ray origin, the stream's counter afterwards), out1 = (unit
// direction, 1 if the ray is bit for bit the pinhole's cameraRay through the same position, else 0),
// out2 = (the jittered position in pixels, 0, 0).
#include "common/rng.glsl"
#include "common/camera.glsl"

uniform uint uSeed;
uniform uint uSample;

layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;

void main() {
    rngInit(uSeed, uvec2(gl_FragCoord.xy), uSample);
    vec2 position = floor(gl_FragCoord.xy) + rand2();
    Ray ray = primaryRay(position);
    float counter = float(rngKey.w);
    Ray pinhole = cameraRay(position);
    bool same = all(equal(ray.origin, pinhole.origin)) && all(equal(ray.dir, pinhole.dir));
    out0 = vec4(ray.origin, counter);
    out1 = vec4(ray.dir, same ? 1.0 : 0.0);
    out2 = vec4(position, 0.0, 0.0);
}
