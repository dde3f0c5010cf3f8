// The first denoising pass: from the accumulation (src/render/render_targets.h; the guides come from
// glsl/passes/guides.glsl) to what the filters work on. Per pixel: the mean colour, divided by its
// first-hit albedo when uDemodulate is 1 (so that a filter smooths the light, not the texture;
// finish.frag.glsl multiplies the albedo back), the variance of that mean's luminance, the guides, and
// the albedo to multiply back.
#include "common/luminance.glsl"
#include "denoise/pixel_class.glsl"

uniform sampler2D uSum;          // (sum of radiance, samples)
uniform sampler2D uSquares;      // (sum of squared radiance, dropped samples)
uniform sampler2D uCounters;     // (rays, samples whose first hit was an emitter, first hits, 0)
uniform sampler2D uNormalDepth;  // (sum of first-hit normals, sum of first-hit distances)
uniform sampler2D uAlbedoSum;    // (sum of first-hit albedos, guide samples)
uniform sampler2D uSplatSum;    // bdpt's light image (render/light_splat.h): (sum of contributions, rays)
uniform float uLightPaths;       // light paths per pixel behind uSplatSum; 0: no light image
uniform int uDemodulate;

// Albedos below this are raised to it before dividing: a black surface must not blow up its noise.
const float kMinAlbedo = 0.01;
// Below this many samples the per-pixel variance is too unreliable; the variance pass estimates it
// from the neighbourhood instead (SVGF sec. 4.2 does so for histories shorter than 4 frames).
const float kMinSamplesForVariance = 4.0;

layout(location = 0) out vec4 outColor;   // (colour, luminance variance of its mean; -1: estimate it)
layout(location = 1) out vec4 outGuide;   // (unit normal or 0, mean distance or pixel class)
layout(location = 2) out vec4 outAlbedo;  // (albedo to multiply back, 0)

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(uSum, p, 0);
    float n = sum.a;
    if (n == 0.0) {  // not rendered yet (a tile of an unfinished pass): its neighbours fill it in
        outColor = vec4(0.0);
        outGuide = vec4(0.0, 0.0, 0.0, kUnrendered);
        outAlbedo = vec4(1.0, 1.0, 1.0, 0.0);
        return;
    }
    vec3 mean = sum.rgb / n;
    // bdpt's estimate is the camera mean plus the light image over the light paths (Accumulation::mean);
    // the variance below stays the camera image's.
    if (uLightPaths > 0.0) mean += texelFetch(uSplatSum, p, 0).rgb / uLightPaths;
    vec4 normalDepth = texelFetch(uNormalDepth, p, 0), albedoSum = texelFetch(uAlbedoSum, p, 0);
    float guideSamples = albedoSum.a;  // fewer than n after a resumed render (guides are not saved)
    vec3 normal = vec3(0.0), albedo = vec3(1.0);
    float depth = 0.0;
    bool emitter = false;
    if (guideSamples > 0.0) {
        vec3 meanNormal = normalDepth.xyz / guideSamples;
        normal = dot(meanNormal, meanNormal) > 1e-12 ? normalize(meanNormal) : vec3(0.0);
        depth = normalDepth.w / guideSamples;
        // An emitter's radiance is not albedo times light, and a pixel that saw only background has no
        // albedo: neither is demodulated.
        emitter = texelFetch(uCounters, p, 0).y > 0.0;
        if (!emitter && uDemodulate == 1 && depth > 0.0) albedo = max(albedoSum.rgb / guideSamples, kMinAlbedo);
    }
    float variance = -1.0;
    if (n >= kMinSamplesForVariance) {
        vec3 squares = texelFetch(uSquares, p, 0).rgb;
        // Per channel, the variance of the mean, as Accumulation::varianceOfMean computes it.
        vec3 channels = max(squares - n * mean * mean, 0.0) / ((n - 1.0) * n);
        // Luminance is a weighted sum of the channels, whose covariances are not accumulated: take them
        // as fully correlated (one path carries all three), which makes standard deviations add.
        float deviation = luminance(sqrt(channels) / albedo);
        variance = deviation * deviation;
    }
    outColor = vec4(mean / albedo, variance);
    outGuide = vec4(normal, emitter ? kEmitter : depth);
    outAlbedo = vec4(albedo, 0.0);
}
