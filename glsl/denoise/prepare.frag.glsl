// The first denoising pass: from the accumulation (src/render/render_targets.h; the guides come from
// glsl/passes/guides.glsl) to what the filters work on. Per pixel: the mean colour, divided by its
// first-hit albedo when uDemodulate is 1 (so that a filter smooths the light, not the texture;
// finish.frag.glsl multiplies the albedo back), the variance of that mean's luminance, the guides, and
// the albedo to multiply back.
#include "common/luminance.glsl"
#include "denoise/accumulated_pixel.glsl"
#include "denoise/pixel_class.glsl"

uniform sampler2D uSquares;  // (sum of squared radiance, dropped samples)
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
    vec3 mean = a.mean;  // with bdpt's light image; the variance below stays the camera image's
    // An emitter's radiance is not albedo times light, and a pixel that saw only background has no
    // albedo: neither is demodulated.
    vec3 albedo = vec3(1.0);
    if (a.hasGuides && !a.emitter && uDemodulate == 1 && a.depth > 0.0) albedo = max(a.albedo, kMinAlbedo);
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
    outGuide = vec4(a.normal, a.emitter ? kEmitter : a.depth);
    outAlbedo = vec4(albedo, 0.0);
}
