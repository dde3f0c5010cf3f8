// Next-event estimation with multiple importance sampling (Veach 1997, ch. 9): at every vertex a
// light sample and a BSDF sample each estimate direct lighting, and the power heuristic weighs the
// two so that each covers the paths the other samples badly. Light found by a BSDF-sampled ray is
// weighted against the density light sampling would have had for it; after a delta lobe (mirror,
// glass), which light sampling cannot reach, it counts in full.
//
// Caustics seen directly (CAUSTICS_LIGHT_TRACED, --caustics light): a path whose first vertex x1 sampled
// a smooth lobe and whose next vertices x2 .. x_m (m >= 2) each sampled a caster's lobe (a delta lobe, or
// a glossy caster's: bsdf.glsl, casterLobe) before x_{m+1} on an emitter (a floor lit through a glass
// ball, a wall lit by a gold sphere's highlight) is found here only when the BSDF sample at x1 happens to
// aim, through the glass or off the metal, at the light. Light tracing finds it from the other end: the
// light-tracing pass (passes/light_trace.frag.glsl) follows light through the caster vertices to x1 and
// joins x1 to the camera (bdpt's strategy t = 1, Veach 1997 section 10.2). So it does for the light such a
// caustic sends on: x1 .. x_j (j <= CAUSTIC_SMOOTH_BOUNCES) sampled smooth lobes and x_{j+1} .. x_m
// casters' (a wall lit by the caustic on the floor), which a camera path finds only when x_j's BSDF
// sample aims through the glass at the light: a firefly. The two estimators split path space: the light
// pass sums exactly these paths, with m + 1 <= LIGHT_RECORDS (its light subpaths' length,
// bdpt_subpaths.glsl), and this integrator leaves exactly those out, whether it would find them by a BSDF
// sample or, at a glossy caster x_m, by a light sample; so their sum is unbiased without weights.
#include "common/sampling.glsl"
#include "common/intersect.glsl"
#include "common/bsdf.glsl"
#include "common/surface.glsl"
#include "common/lights.glsl"
#include "common/render_uniforms.glsl"

// Whether a path of `smoothVertices` smooth vertices x1 .. x_j, then casters' lobes, reaching an emitter at
// `emitterDepth` is one the light pass sums.
bool lightPassSums(int smoothVertices, int emitterDepth) {
    return smoothVertices >= 1 && smoothVertices <= CAUSTIC_SMOOTH_BOUNCES && emitterDepth < LIGHT_RECORDS;
}

// A camera path as it is extended vertex by vertex: what the path carries from one vertex to the next. The
// pass (passes/trace.frag.glsl) extends the paths of its samples one after another with no gap between
// them (PATH_SEGMENTS), and radiance() below traces one whole path.
#define PATH_SEGMENTS 1
struct CameraPath {
    Ray ray;       // the next segment's
    int depth;     // the vertex the next segment reaches: 0 the first hit
    vec3 L, beta;  // the light found so far, and the throughput up to the ray's origin
    float etaScale;  // for the roulette (survivesRoulette)
    float lastPdf;   // solid-angle density of the ray's direction
    vec3 lastPosition;  // the vertex it left from, where sampleLight would have sampled
    vec3 lastNormal;    // its shading normal (the light tree's choice depends on it)
    bool fullWeight;    // camera rays and delta bounces: no light sample competed
    // The path so far, for the light pass's split: x1 .. x_j sampled smooth lobes (j = causticSmooth), and
    // once causticCast, every vertex since x_{j+1} a caster's lobe. -1: not such a path (x1 sampled a
    // caster's lobe, or a smooth lobe came after one).
    int causticSmooth;
    bool causticCast;
};

CameraPath startPath(Ray ray) {
    return CameraPath(ray, 0, vec3(0.0), vec3(1.0), 1.0, 0.0, ray.origin, vec3(0.0, 0.0, 1.0), true, 0, false);
}

// Traces the path's next segment and adds the light it finds at the vertex it reaches (hit, or by a light
// sample there); then samples the direction of the segment after. False when the path has ended.
bool extendPath(inout CameraPath p) {
    Ray ray = p.ray;
    int depth = p.depth;
    Hit hit;
    if (!traceClosest(ray, hit)) {
        vec3 Le = environmentRadiance(ray.dir);
        addLight(p.L, p.beta * Le * (p.fullWeight ? 1.0 : powerHeuristic(p.lastPdf, environmentPdf(ray.dir))), depth);
        return false;
    }
    Surface s = surfaceAt(ray, hit);
    applyDispersion(s, p.beta);
    absorbInside(s, hit.t, p.beta);
    vec3 Le = emittedRadiance(s);
    // Whether the light pass sums this path, should it end on an emitter here.
    bool lightPassPath = p.causticCast && lightPassSums(p.causticSmooth, depth);
#if CAUSTICS_LIGHT_TRACED
    // the light pass's; an unlit surface is no light, which the light pass cannot start from
    if (lightPassPath && s.material.type != MATERIAL_UNLIT) Le = vec3(0.0);
#endif
    if (Le != vec3(0.0))
        addLight(p.L, p.beta * Le * (p.fullWeight ? 1.0 : powerHeuristic(p.lastPdf, lightPdf(p.lastPosition, p.lastNormal, ray, hit))), depth);
    if (depth == uMaxDepth) return false;

    vec3 wo = toLocal(s, -ray.dir);
    // A light sample at a glossy caster after smooth vertices (x_m above, the light x_{m+1} at depth +
    // 1) closes a path the light pass sums.
    bool lightPassSample = isGlossyCaster(s.material) && lightPassSums(p.causticSmooth, depth + 1);
    bool lightSample = !isDeltaOnly(s.material);
#if CAUSTICS_LIGHT_TRACED
    lightSample = lightSample && !lightPassSample;  // the light pass's
#endif
    if (lightSample) {
        LightSample ls = sampleLight(s.position, s.shadingNormal);
        vec3 wi = toLocal(s, ls.dir);
        if (ls.pdf > 0.0 && sameSide(s, wi, ls.dir)) {
            vec3 f = bsdfEval(s.material, wo, wi, s.eta);
            if (f != vec3(0.0) && lightVisible(s, ls)) {
                float w = ls.delta ? 1.0 : powerHeuristic(ls.pdf, bsdfPdf(s.material, wo, wi, s.eta));
                // A punctual light (point, spot, directional) is a delta light that only light
                // sampling can find: weight 1, as in pbrt-v4's PathIntegrator::SampleLd (section
                // 13.4). The light such a light sends through a mirror or smooth glass onto a diffuse
                // surface (a caustic) no camera path can find: the light pass does (above).
                addLight(p.L, p.beta * f * ls.radiance * w / ls.pdf, depth + 1);
            }
        }
    }

    BsdfSample bs;
    BounceNumbers u = drawBounceNumbers(depth);
    if (!bsdfSample(s.material, wo, u.bsdf, s.eta, bs)) return false;
    vec3 dir = toWorld(s, bs.wi);
    if (!sameSide(s, bs.wi, dir)) return false;
    p.beta *= bs.weight;
    p.etaScale *= refractionScale(bs, s);
    p.lastPdf = bs.pdf;
    p.lastPosition = s.position;
    p.lastNormal = s.shadingNormal;
    p.fullWeight = bs.delta;
    if (p.causticSmooth >= 0) {
        bool caster = casterLobe(bs, s.material);
        if (!caster && !p.causticCast)
            ++p.causticSmooth;
        else if (caster && p.causticSmooth > 0)
            p.causticCast = true;
        else
            p.causticSmooth = -1;
    }
#ifdef NORMAL_MAPPED_SURFACES
    if (bs.delta && bentDelta(s, -ray.dir, dir)) p.causticSmooth = -1;  // no light subpath follows it
#endif
    if (!survivesRoulette(p.beta, p.etaScale, bs.delta, depth, u.roulette)) return false;
    p.ray = spawnRay(s, dir);
    p.depth = depth + 1;
    return true;
}

// The path's radiance estimate, once extendPath has ended it.
vec3 pathRadiance(CameraPath p) { return p.L + takeIndirect(); }

vec3 radiance(Ray ray) {
    CameraPath p = startPath(ray);
    while (extendPath(p)) {}
    return pathRadiance(p);
}
