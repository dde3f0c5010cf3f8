// Shows the accumulation on screen: the per-pixel mean (sum / samples), through the display transform
// or, for count views, a heat map from 0 to uHeatMax. The accumulation may be smaller than the
// viewport (the viewer renders at reduced resolution while the camera moves): it is scaled up.
#include "common/tone_map.glsl"

uniform sampler2D uSum;  // (radiance sum, samples)
uniform sampler2D uSplatSum;  // bdpt's light image (render/light_splat.h): (sum of contributions, rays)
uniform float uLightPaths;    // its light paths per pixel N; 0: no light image
uniform vec2 uViewport;
uniform float uExposure;
uniform int uToneMap;
uniform float uHeatMax;  // > 0: show a heat map of the red channel instead
uniform int uSplitLine;  // 1: draw a line down the middle (split view)

out vec4 color;

void main() {
    ivec2 size = textureSize(uSum, 0);
    ivec2 p = min(ivec2(gl_FragCoord.xy * vec2(size) / uViewport), size - 1);
    vec4 s = texelFetch(uSum, p, 0);
    vec3 mean = s.a > 0.0 ? s.rgb / s.a : vec3(0.0);
    if (uLightPaths > 0.0) mean += texelFetch(uSplatSum, p, 0).rgb / uLightPaths;
    vec3 c = uHeatMax > 0.0 ? heatMap(mean.r / uHeatMax) : displayEncode(mean, uExposure, uToneMap);
    if (uSplitLine == 1 && abs(gl_FragCoord.x - 0.5 * uViewport.x) < 1.0) c = vec3(1.0);
    color = vec4(c, 1.0);
}
