// The first denoising pass: from the accumulation (src/render/render_targets.h; the guides come from
// glsl/passes/guides.glsl) to what the filters work on. Per pixel: the mean colour, divided by its
// first-hit albedo when uDemodulate is 1 (so that a filter smooths the light, not the texture;
// finish.frag.glsl multiplies the albedo back), the variance of that mean's luminance, the guides, and
// the albedo to multiply back.
#include "common/luminance.glsl"
#include "denoise/accumulated_pixel.glsl"
#include "denoise/pixel_class.glsl"

uniform sampler2D uSquares;       // (sum of squared radiance, dropped samples)
uniform sampler2D uSplatSquares;  // bdpt's light image: (sum of squared contributions, dropped); with uLightPaths
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
    AccumulatedPixel a = readAccumulatedPixel(p);
    float n = a.samples;
    if (n == 0.0) {  // not rendered yet (a tile of an unfinished pass): its neighbours fill it in
        outColor = vec4(0.0);
        outGuide = vec4(0.0, 0.0, 0.0, kUnrendered);
        outAlbedo = vec4(1.0, 1.0, 1.0, 0.0);
        return;
    }
    vec3 mean = a.mean;  // with bdpt's light image
    // An emitter's radiance is not albedo times light, and a pixel that saw only background has no
    // albedo: neither is demodulated.
    vec3 albedo = vec3(1.0);
    if (a.hasGuides && !a.emitter && uDemodulate == 1 && a.depth > 0.0) albedo = max(a.albedo, kMinAlbedo);
    float variance = -1.0;
    if (n >= kMinSamplesForVariance) {
        // Per channel, the variance of the mean, as Accumulation::varianceOfMean computes it. The camera
        // part from the camera samples' own mean: uSquares holds their squares only, so subtracting
        // n (camera + light)^2 would remove too much, often clamping the variance to 0 (the a-trous filter
        // then kept bdpt's noise as detail: its error grew from 2 to 4 spp, where this estimate starts).
        vec3 squares = texelFetch(uSquares, p, 0).rgb;
        vec3 channels = max(squares - n * a.cameraMean * a.cameraMean, 0.0) / ((n - 1.0) * n);
        // The light image is a second, independent estimator added to the camera's (they share only
        // the light subpaths of this pixel's own samples, 1 / (W H) of those that land here), so its
        // variance adds: it is noise in this pixel's estimate like the camera's, and leaving it out would
        // make the filter keep light-tracing noise as detail. As Accumulation::varianceOfMean: M = N W H
        // paths of contributions X (most of them 0 here), Var = M Var(X) / N^2, estimated as
        // sum X^2 / N^2 - (splat sum / N)^2 / M.
        if (uLightPaths > 0.0) {
            vec3 splat = texelFetch(uSplatSum, p, 0).rgb / uLightPaths;
            vec2 size = vec2(textureSize(uSplatSum, 0));
            float paths = uLightPaths * size.x * size.y;
            vec3 splatSquares = texelFetch(uSplatSquares, p, 0).rgb;
            channels += max(splatSquares / (uLightPaths * uLightPaths) - splat * splat / paths, 0.0);
        }
        // Luminance is a weighted sum of the channels, whose covariances are not accumulated: take them
        // as fully correlated (one path carries all three), which makes standard deviations add.
        float deviation = luminance(sqrt(channels) / albedo);
        variance = deviation * deviation;
    }
    outColor = vec4(mean / albedo, variance);
    outGuide = vec4(a.normal, a.emitter ? kEmitter : a.depth);
    outAlbedo = vec4(albedo, 0.0);
}
