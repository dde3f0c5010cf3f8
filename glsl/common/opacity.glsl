// Coverage (glTF alphaMode MASK and BLEND, MTL d and map_d) and single-sided surfaces (glTF doubleSided
// false), decided during traversal: a hit the surface does not cover is skipped as if the triangle were
// not there. Coverage holds for camera, bounce and shadow rays alike; single-sidedness for the camera's
// view only (below). Compiled in only when some material needs it
// (SURFACE_OPACITY), and asked only for triangles whose flags say so (the triangles' third texel,
// src/pack/layout.h), so that other scenes pay nothing.
//
// MASK covers where alpha >= alphaCutoff, deterministically. BLEND covers with probability alpha
// ("stochastic transparency", Enderton et al. 2010): treating alpha as the fraction of the pixel's
// footprint the surface covers, the expected radiance through it is alpha times the surface's plus
// (1 - alpha) times what lies behind, which is what the glTF specification's blend means, without sorting
// and for every kind of ray. The coin is a hash of the ray and the triangle (as hashed alpha testing
// hashes the position: Wyman & McGuire 2017): no sampler dimension is consumed, so the sample sequences
// of the other decisions stay aligned, and one ray decides the same way for a triangle every time.
#include "common/ray.glsl"
#include "common/rng.glsl"
#include "common/scene_data.glsl"
#include "common/textures.glsl"
#include "common/camera.glsl"

#ifdef SURFACE_OPACITY
// Material m's alpha at barycentrics b of triangle i (alpha times its alpha map's A channel), then its
// coverage: 0 or 1 for MASK (against the cutoff), the alpha itself for BLEND, 1 for OPAQUE.
float materialCoverage(int m, int i, vec2 b) {
    vec4 a = materialTexel(m * MATERIAL_TEXELS + MATERIAL_ALPHA_TEXEL);  // (map, alpha, cutoff, mode)
    float alpha = a.y;
#ifdef SURFACE_TEXTURES
#if HAS_MAP(ALPHA_MAP_BIT)
    if (a.x >= 0.0) alpha *= sampleLinearTexture(int(a.x), fetchTexcoord(i, b)).a;
#endif
#endif
#ifdef VERTEX_COLORS
    alpha *= fetchVertexColor(i, b).a;
#endif
    if (a.w == 1.0) return alpha >= a.z ? 1.0 : 0.0;  // fp::AlphaMode::Mask
    return a.w == 2.0 ? alpha : 1.0;                  // Blend, Opaque
}

// A number uniform in [0, 1) from the ray's origin and direction and the triangle's index (pcg4d,
// rng.glsl).
float coverageHash(Ray ray, int i) {
    uvec3 o = floatBitsToUint(ray.origin), d = floatBitsToUint(ray.dir);
    uvec4 h = pcg4d(uvec4(o.x ^ (d.y << 7u), o.y ^ (d.z << 13u), o.z ^ (d.x << 3u), uint(i) ^ d.x ^ d.y ^ d.z));
    return float(h.x >> 8u) * (1.0 / 16777216.0);
}

// A single-sided surface (glTF's back-face culling) is not there for the camera when it is seen from
// behind (from the side its counter-clockwise front, surface.glsl's frontFace, does not face). Only the
// camera's view: light and every other ray meet both of its sides, so that such a wall still casts
// shadows and holds light in, and visibility stays symmetric, which bidirectional estimators need (a
// surface that let light through one way only would be seen differently by light subpaths). Camera
// rays are the rays from the lens (camera.glsl isCameraRay, asked of the world ray); bdpt's joins of light vertices to the
// eye are traced the other way and say so with gTowardTheEye, and check the joined vertex's own side
// (light_trace.frag.glsl).
bool gTowardTheEye = false;
bool gCameraTrace = false;  // whether the traversal under way is of a camera ray (set from the world ray)

// Whether the hit of `ray` at barycentrics b of triangle i (whose flags are not 0) counts.
bool coversHit(Ray ray, TriangleData tri, int i, vec2 b) {
    int flags = int(tri.flags);
    if ((flags & TRIANGLE_SINGLE_SIDED_FLAG) != 0) {
        bool front = dot(cross(tri.e1, tri.e2), ray.dir) < 0.0;
        if (gTowardTheEye ? front : !front && gCameraTrace) return false;
    }
    if ((flags & TRIANGLE_ALPHA_FLAG) == 0) return true;
    float coverage = materialCoverage(tri.material, i, b);
    return coverage >= 1.0 || (coverage > 0.0 && coverageHash(ray, i) < coverage);
}
#endif
