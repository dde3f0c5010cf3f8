// What the denoising filters share: the prepared guides and the edge-stopping weights of the spatial
// filter of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided Filtering: Real-Time
// Reconstruction for Path-Traced Global Illumination", HPG), section 4.4, eqs. 3-5.

// (unit first-hit normal, 0 if every sample missed; mean first-hit distance, or a pixel class)
uniform sampler2D uGuide;

const float kSigmaDepth = 1.0;      // sigma_z of eq. 3 (SVGF's value)
const float kSigmaNormal = 128.0;   // sigma_n of eq. 4 (SVGF's value)
const float kSigmaLuminance = 4.0;  // sigma_l of eq. 5 (SVGF's value)

bool inImage(ivec2 q) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, textureSize(uGuide, 0))); }

// Whether a pixel with this guide may contribute to a filtered pixel: rendered, and not an emitter.
bool isNeighbour(vec4 guide) { return guide.w >= 0.0; }

// The screen-space depth gradient at p (SVGF takes it from the rasteriser; here the guides are an
// image): per axis the one-sided difference of smaller magnitude, so that a neighbour across a depth
// edge does not count.
vec2 depthGradient(ivec2 p, float z) {
    vec2 gradient;
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 step = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        float best = 1e30;
        for (int side = -1; side <= 1; side += 2) {
            ivec2 q = p + side * step;
            if (!inImage(q)) continue;
            float zq = texelFetch(uGuide, q, 0).w;
            if (zq < 0.0) continue;
            float d = zq - z;
            if (abs(d) < abs(best)) best = d;
        }
        gradient[axis] = best == 1e30 ? 0.0 : abs(best);
    }
    return gradient;
}

// Eq. 3: the depth difference against what the local gradient predicts over the offset. The small
// term relative to the depth keeps a fronto-parallel plane (zero gradient) from splitting on rounding.
float depthWeight(float zp, float zq, vec2 gradient, vec2 offset) {
    float predicted = kSigmaDepth * abs(dot(gradient, offset)) + 1e-3 * zp + 1e-20;
    return exp(-abs(zp - zq) / predicted);
}

// Eq. 4. A pixel whose samples all missed has no normal: it joins only others like it.
float normalWeight(vec3 np, vec3 nq) {
    bool missP = np == vec3(0.0), missQ = nq == vec3(0.0);
    if (missP || missQ) return missP == missQ ? 1.0 : 0.0;
    float w = max(0.0, dot(np, nq));
    for (int i = 0; i < 7; ++i) w *= w;  // ^128 = ^kSigmaNormal, by squaring (cheaper than pow)
    return w;
}

// w_n w_z of pixel q for the filtered pixel p. A pixel without samples (kUnrendered) has no geometry
// to compare: only the other weights apply.
float geometryWeight(vec4 guideP, vec4 guideQ, vec2 gradient, vec2 offset) {
    if (guideP.w < 0.0) return 1.0;
    return normalWeight(guideP.xyz, guideQ.xyz) * depthWeight(guideP.w, guideQ.w, gradient, offset);
}

// Eq. 5: the luminance difference against the noise expected at p, sqrt of its (prefiltered)
// variance; the epsilon keeps a noise-free pixel from dividing by zero.
float luminanceWeight(float lp, float lq, float varianceP) {
    return exp(-abs(lp - lq) / (kSigmaLuminance * sqrt(max(varianceP, 0.0)) + 1e-10));
}
