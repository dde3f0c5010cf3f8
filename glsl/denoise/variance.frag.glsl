// Where the prepare pass left no variance (fewer than 4 samples), estimate it spatially as SVGF does
// for short histories (Schied et al. 2017, sec. 4.2): the variance of the luminance of the 7x7
// neighbourhood, weighted by the normal and depth edge-stopping functions (eqs. 3 and 4). The
// neighbours are means of as many samples, so their spread estimates the noise of the mean (plus any
// real detail, which errs on the side of smoothing).
#include "common/luminance.glsl"
#include "denoise/edge_stopping.glsl"

uniform sampler2D uColor;  // (colour, variance or -1) from prepare.frag.glsl

out vec4 outColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(uColor, p, 0);
    vec4 guide = texelFetch(uGuide, p, 0);
    if (c.a >= 0.0 || !isNeighbour(guide)) {
        outColor = vec4(c.rgb, max(c.a, 0.0));
        return;
    }
    vec2 gradient = depthGradient(p, guide.w);
    float weights = 0.0, moment1 = 0.0, moment2 = 0.0;
    for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!inImage(q)) continue;
            vec4 g = texelFetch(uGuide, q, 0);
            if (!isNeighbour(g)) continue;
            float w = geometryWeight(guide, g, gradient, vec2(dx, dy));
            float l = luminance(texelFetch(uColor, q, 0).rgb);
            weights += w;
            moment1 += w * l;
            moment2 += w * l * l;
        }
    // The centre always counts with weight 1, so weights >= 1.
    moment1 /= weights;
    outColor = vec4(c.rgb, max(moment2 / weights - moment1 * moment1, 0.0));
}
