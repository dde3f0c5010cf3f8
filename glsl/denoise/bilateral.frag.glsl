// A joint (cross) bilateral filter of the mean colour (Tomasi and Manduchi 1998, "Bilateral Filtering
// for Gray and Color Images"; joint with guide images: Eisemann and Durand 2004, Petschnigg et al.
// 2004). The weight of neighbour q of pixel p is
//   exp(-|p - q|^2 / (2 sigma_s^2)) * exp(-|t(c_p) - t(c_q)|^2 / (2 sigma_r^2)) * w_n * w_z
// a spatial Gaussian, a range Gaussian on the colour, and the normal and depth guides of SVGF's
// eqs. 3-4 (edge_stopping.glsl). t(c) = c / (1 + luminance(c)) compresses the colour the way a display
// would, so that sigma_r is a fraction of the visible range and a firefly's pull is bounded.
#include "common/luminance.glsl"
#include "denoise/pixel_class.glsl"
#include "denoise/edge_stopping.glsl"

uniform sampler2D uColor;  // (mean colour, unused)

const float kSigmaSpatial = 2.0;  // pixels; taps out to 2 sigma_s (a 9x9 window)
const float kSigmaRange = 0.25;   // on the compressed colour, whose values lie in [0, 1)

out vec4 outColor;

vec3 compressed(vec3 c) { return c / (1.0 + luminance(c)); }

void main() {
    const int radius = int(2.0 * kSigmaSpatial);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 guide = texelFetch(uGuide, p, 0);
    if (guide.w == kEmitter) {
        outColor = texelFetch(uColor, p, 0);
        return;
    }
    vec3 tp = compressed(texelFetch(uColor, p, 0).rgb);
    vec2 gradient = depthGradient(p, guide.w);
    vec3 color = vec3(0.0);
    float weights = 0.0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (!inImage(q)) continue;
            vec4 g = texelFetch(uGuide, q, 0);
            if (!isNeighbour(g)) continue;
            vec3 c = texelFetch(uColor, q, 0).rgb;
            vec3 dt = tp - compressed(c);
            float w = exp(-float(dx * dx + dy * dy) / (2.0 * kSigmaSpatial * kSigmaSpatial)) *
                      exp(-dot(dt, dt) / (2.0 * kSigmaRange * kSigmaRange)) * geometryWeight(guide, g, gradient, vec2(dx, dy));
            color += w * c;
            weights += w;
        }
    outColor = vec4(weights > 0.0 ? color / weights : vec3(0.0), 0.0);
}
