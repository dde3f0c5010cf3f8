// The light tree (src/pack/light_tree.h; Conty Estevez & Kulla 2018, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting", HPG): next-event estimation chooses an emitter by descending a
// binary tree whose nodes bound their emitters (box, power, cone of normals), at each node taking a
// child with probability proportional to an upper bound of the light it can send to the shading point.
// Far emitters, emitters turned away and emitters below the surface's horizon are then chosen rarely,
// where a choice by power alone (lights.glsl pickLight) spends samples on them as on any other.
// The tree is a complete heap in the lights buffer from texel LIGHT_TREE_FIRST, LIGHT_TREE_DEPTH levels
// below the root; the path to emitter entry e is e's binary digits, most significant first.
//
// LIGHT_TREE (set by the renderer for nee, src/render/renderer.cpp): 1 chooses emitters by the light tree,
// and compiles this file in.
#include "common/scene_data.glsl"

#ifndef LIGHT_TREE
#define LIGHT_TREE 0
#endif
#if LIGHT_TREE

// cos(max(0, a - b)) and sin(max(0, a - b)) for angles a, b in [0, pi], from their cosines and sines.
float cosClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    return cosA >= cosB ? 1.0 : cosA * cosB + sinA * sinB;
}
float sinClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    return cosA >= cosB ? 0.0 : sinA * cosB - cosA * sinB;
}

// An upper bound of the light node k's emitters can send to point p of normal n (the paper's eq. (3),
// with the bounding sphere's half-angle theta_b as the spread of directions from p): power x
// cos(theta') x cos(theta_i') / d^2, where theta' is the angle between the emitters' cone and the
// direction to p less the cone's half-angle and theta_b (0 when it reaches past pi / 2: every emitter
// faces away), theta_i' that between n and the direction to the node less theta_b (either side of the
// surface: a light behind it can still reach it through a transmissive BSDF), and d the distance to the
// box's centre, no less than the sphere's radius.
float lightNodeImportance(int k, vec3 p, vec3 n) {
    vec4 lo = lightTexel(LIGHT_TREE_FIRST + 3 * k);
    if (lo.w <= 0.0) return 0.0;  // an empty node (a padding leaf, or emitters never picked)
    vec4 hi = lightTexel(LIGHT_TREE_FIRST + 3 * k + 1);
    vec3 axis = lightTexel(LIGHT_TREE_FIRST + 3 * k + 2).xyz;
    vec3 d = p - 0.5 * (lo.xyz + hi.xyz);
    float d2 = dot(d, d);
    vec3 diagonal = hi.xyz - lo.xyz;
    float r2 = 0.25 * dot(diagonal, diagonal);
    if (d2 <= r2) return lo.w / max(r2, 1e-30);  // p inside the bounding sphere: no angle bounds
    vec3 w = d * inversesqrt(d2);  // from the node toward p
    float sinB = sqrt(r2 / d2), cosB = sqrt(1.0 - r2 / d2);
    float cosW = dot(axis, w), sinW = sqrt(max(0.0, 1.0 - cosW * cosW));
    float cosO = hi.w, sinO = sqrt(max(0.0, 1.0 - cosO * cosO));
    float cosX = cosClampedDifference(cosW, sinW, cosO, sinO), sinX = sinClampedDifference(cosW, sinW, cosO, sinO);
    float cosTheta = cosClampedDifference(cosX, sinX, cosB, sinB);
    if (cosTheta <= 0.0) return 0.0;
    float cosI = abs(dot(n, w)), sinI = sqrt(max(0.0, 1.0 - cosI * cosI));
    return lo.w * cosTheta * cosClampedDifference(cosI, sinI, cosB, sinB) / d2;
}

// The probability of node k's first child, or -1 when neither child can light p.
float lightTreeFirstChildProbability(int k, vec3 p, vec3 n) {
    float first = lightNodeImportance(2 * k + 1, p, n), second = lightNodeImportance(2 * k + 2, p, n);
    float total = first + second;
    return total > 0.0 ? first / total : -1.0;
}

// An emitter entry for p, chosen with u, which is rescaled to the chosen branch at every level (so that it
// is again uniform, as pickLight's is); pmf: the probability of the choice, 0 when no emitter can light p.
int pickLightTree(vec3 p, vec3 n, inout float u, out float pmf) {
    int k = 0;
    pmf = 1.0;
    for (int level = 0; level < LIGHT_TREE_DEPTH; ++level) {
        float first = lightTreeFirstChildProbability(k, p, n);
        if (first < 0.0) {
            pmf = 0.0;
            return 0;
        }
        if (u < first) {
            u /= first;
            pmf *= first;
            k = 2 * k + 1;
        } else {
            u = (u - first) / (1.0 - first);
            pmf *= 1.0 - first;
            k = 2 * k + 2;
        }
        u = min(u, 0.99999994);
    }
    return k - ((1 << LIGHT_TREE_DEPTH) - 1);
}

// The probability that pickLightTree(p, n) chooses emitter entry e: the same products along e's path,
// so that MIS weighs a BSDF-sampled hit on an emitter with exactly the density of the choice.
float lightTreePmf(vec3 p, vec3 n, int e) {
    int k = 0;
    float pmf = 1.0;
    for (int level = LIGHT_TREE_DEPTH - 1; level >= 0; --level) {
        float first = lightTreeFirstChildProbability(k, p, n);
        if (first < 0.0) return 0.0;
        bool second = ((e >> level) & 1) != 0;
        pmf *= second ? 1.0 - first : first;
        k = 2 * k + (second ? 2 : 1);
    }
    return pmf;
}

// The emitter entry of triangle i (pack/layout.h: the w of its first normal's texel).
int lightEntryOf(int i) { return int(normalTexel(i * NORMAL_TEXELS).w); }
#endif
