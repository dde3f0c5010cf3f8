// One iteration of the edge-avoiding a-trous wavelet filter (Dammertz, Sewtz, Hanika and Lensch 2010,
// "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination Filtering", HPG): a 5x5
// B3-spline kernel h whose taps lie uStep = 2^i pixels apart, i = 0..4, steered as in the spatial
// filter of SVGF (Schied et al. 2017):
//   c_{i+1}(p) = sum_q h(q) w(p,q) c_i(q) / sum_q h(q) w(p,q)                     (eq. 1)
//   Var(c_{i+1}(p)) = sum_q h(q)^2 w(p,q)^2 Var(c_i(q)) / (sum_q h(q) w(p,q))^2   (eq. 2)
// with w = w_z w_n w_l (eqs. 3-5, edge_stopping.glsl) and w_l using the variance at p filtered by a
// 3x3 Gaussian first (eq. 5's g_3x3). Colour and variance are filtered together, so the luminance
// weight tightens as the noise goes.
#include "common/luminance.glsl"
#include "denoise/pixel_class.glsl"
#include "denoise/edge_stopping.glsl"

// (demodulated colour, luminance variance of its mean). A pixel the real-time pipeline passes through
// unfiltered (denoise/unsettled.frag.glsl) keeps its input, where the variance may be -1 (not estimated):
// as a neighbour it counts as 0.
uniform sampler2D uColor;
uniform int uStep;
out vec4 outColor;

// g_3x3 of eq. 5: the binomial 3x3 Gaussian (1/4, 1/2, 1/4 per axis) over the pixels that have samples.
float prefilteredVariance(ivec2 p) {
    const float k[3] = float[3](0.25, 0.5, 0.25);
    float sum = 0.0, weights = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!inImage(q) || !isNeighbour(texelFetch(uGuide, q, 0))) continue;
            float w = k[dx + 1] * k[dy + 1];
            sum += w * max(texelFetch(uColor, q, 0).a, 0.0);
            weights += w;
        }
    return weights > 0.0 ? sum / weights : 0.0;
}

void main() {
    const float h[5] = float[5](1.0 / 16.0, 1.0 / 4.0, 3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);  // B3 spline
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 guide = texelFetch(uGuide, p, 0);
    if (guide.w == kEmitter) {
        outColor = texelFetch(uColor, p, 0);
        return;
    }
    float lp = luminance(texelFetch(uColor, p, 0).rgb);
    float varianceP = prefilteredVariance(p);
    vec2 gradient = depthGradient(p, guide.w);
    vec3 color = vec3(0.0);
    float variance = 0.0, weights = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 offset = ivec2(dx, dy) * uStep;
            ivec2 q = p + offset;
            if (!inImage(q)) continue;
            vec4 g = texelFetch(uGuide, q, 0);
            if (!isNeighbour(g)) continue;
            vec4 c = texelFetch(uColor, q, 0);
            float w = h[dx + 2] * h[dy + 2] * geometryWeight(guide, g, gradient, vec2(offset)) *
                      luminanceWeight(lp, luminance(c.rgb), varianceP);
            color += w * c.rgb;
            variance += w * w * max(c.a, 0.0);
            weights += w;
        }
    // A pixel without samples has weight 0 itself and takes its neighbours' value (0 if none has any).
    outColor = weights > 0.0 ? vec4(color / weights, variance / (weights * weights)) : vec4(0.0);
}
