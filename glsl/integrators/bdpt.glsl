// Bidirectional path tracing with multiple importance sampling (Veach 1997, ch. 10; the ratio form of
// the weights follows the presentation of pbrt-v3, section 16.3).
//
// Each sample traces a light subpath y0 y1 ... (y0 uniformly on an emissive triangle picked by power, as
// lights.glsl picks it; the first direction cosine-weighted from the emitting front face) and a camera
// subpath z0 z1 ... (z0 the pinhole, or a point of a thin lens), and joins every prefix pair: strategy
// (s, t) uses s light and t camera vertices, a path of s + t vertices and s + t - 1 edges (bounces =
// s + t - 2, so --max-depth D allows s + t <= D + 2, exactly the paths nee and bsdf sum).
//
// Strategies included (all of them for a pinhole camera, up to the light-subpath limit below; a thin lens
// is not part of the scene, so t = 0, a light subpath that reaches it, is left out as in pbrt):
//   s = 0, t >= 2  the camera subpath hits the front face of an emitter (or escapes to the environment)
//   s = 1, t >= 2  next-event style: z_{t-1} joined to a point sampled afresh on an emitter
//   s >= 2, t >= 2 z_{t-1} joined to y_{s-1} by one shadow ray
//   s >= 1, t = 1  light tracing: y_{s-1} (y0 too, an emitter facing the camera) joined to the pinhole (or
//                  to a point sampled on the lens) by one shadow ray. Its contribution lands on the pixel y_{s-1} projects to, not on the
//                  pixel whose sample traced the light subpath, so this file does not compute it: the
//                  light-tracing pass (passes/light_trace.frag.glsl, src/render/light_splat.h) traces the
//                  same light subpath of each sample (traceLightSubpathFor) and adds those contributions
//                  into a light image; the estimate is camera image mean + light image / N, N the light
//                  paths per pixel so far (pbrt-v3 16.3: splats are scaled by 1 / spp).
//   t = 0 cannot happen with a pinhole camera (its position is a point nothing can hit), and is not used
//        with a lens.
// The weights (misWeight) are the power heuristic over exactly these strategies, with
// s <= BDPT_MAX_LIGHT_VERTICES. A caustic seen directly on a diffuse floor through smooth glass
// (light -> glass -> glass -> floor -> camera) has two joinable edges, at its two ends: s = 0 (the camera
// subpath reaches the light through the glass, as in nee) and t = 1 (the light subpath reaches the floor
// through the glass and the floor point is joined to the camera), and t = 1 is the good one for a small
// light. Caustic light bounced once more off a diffuse surface is found by the s >= 2 joins (light ->
// glass -> glass -> floor -> wall -> camera: s = 4 joins the wall to the floor point).
//
// Punctual lights (point, spot, directional: lights.glsl) are picked with the emitter triangles, by
// power, for s = 1 and as light-subpath origins. They are delta lights, which pbrt-v3 16.3 (and pbrt-v4's
// BDPTIntegrator) handle this way, and so does this file: y0 is a delta position (point, spot: density
// pdfPos = 1 times the pick's pmf) or a delta direction (directional: a point on a disk of the scene's
// bounding radius facing the light, density 1 / (pi r^2)); the first direction is uniform over the
// sphere or inside the spot's outer cone, or the light's own. No camera subpath can hit such a light, so
// strategy s = 0 does not exist for their paths (misWeight leaves it out), and (s, t) = (1, 1), the light
// itself seen by the camera, is not drawn, as nee and the camera do not see one either. Every other
// strategy works as for area lights: s = 1 joins z_{t-1} to the light, light tracing (t = 1) starts from
// it, and its delta density cancels from every ratio but the one with s = 0.
//
// Environment light: light subpaths start on emissive triangles and punctual lights only, so light
// arriving from the environment is found by s = 0 alone (a camera subpath that escapes), with weight 1, as
// in the bsdf integrator. That is unbiased but noisy for scenes lit mostly by the environment: use nee
// there.
//
// Fragment-shader limits (fixed arrays, no recursion):
//   BDPT_MAX_LIGHT_VERTICES  light subpath vertices stored (y0..y3: bdpt_subpaths.glsl; the light image has
//                            LIGHT_RECORDS >= 4 records per light path); strategies with more light
//                            vertices are not used, and the weights leave them out.
//   BDPT_MAX_DEPTH           --max-depth is clamped to this (camera vertices z0..z_{D+1} are stored);
//                            above it the image is that of depth BDPT_MAX_DEPTH.
// Russian roulette ends camera subpaths after 3 bounces, as in nee (the survivors are reweighted, so the
// estimate stays unbiased); light subpaths are short and have none.
//
// Shading normals: at a vertex, a direction is usable only if it lies on the same side of the shading
// normal as of the geometric normal, for both directions at the vertex and in every strategy (nee checks
// only the sampled one), and light subpaths use the adjoint BSDF: without the 1/eta^2 radiance scaling on
// refraction and with the shading-normal correction (Veach 1997, ch. 5; pbrt-v3 16.1).
//
// Dispersion: one wavelength per sample, drawn when either subpath first meets a dispersive glass;
// its spectral weight multiplies the contributions of paths that contain such a vertex.
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/intersect.glsl"
#include "common/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "common/surface.glsl"
#include "common/lights.glsl"
#include "common/camera.glsl"
#include "common/render_uniforms.glsl"
#include "integrators/bdpt_subpaths.glsl"

// Strategy s = 1: z_{t-1} joined to a point sampled afresh on an emitter (by power, then uniformly on the
// triangle): the unweighted contribution beta_z f(z -> y) Le(y -> z) |cos(theta_y)| / (r^2 p_A(y)).
// Or to a punctual light picked by power (pmf): beta_z f(z -> y) I(y -> z) / (r^2 pmf), or for a
// directional light beta_z f(z -> -w) E / pmf (pbrt-v3 16.3, "Subpath Connections", s = 1, with a delta
// light's Sample_Li).
vec3 connectToLight(int t) {
    PathVertex c = gCamera[t - 1];
    EmitterPoint e = sampleEmitterPoint();
    PathVertex y;
    vec3 d, Le;
    float scale, zRevLast, pdfFresh;
    bool delta = false;
#if PUNCTUAL_LIGHTS
    if (e.punctual >= 0) {
        PunctualLight l = fetchPunctualLight(e.punctual);
        delta = true;
        pdfFresh = e.pmf;
        if (l.type == PUNCTUAL_DIRECTIONAL) {
            d = -l.direction;
            Le = l.intensity;
            scale = 1.0 / e.pmf;
            // The light subpath would reach c from the disk with its area density projected onto c.
            zRevLast = abs(dot(c.ng, d)) / (PI * l.radius * l.radius);
            // A point beyond the scene's bounding sphere (c lies inside it) ends the shadow ray, as pbrt-v3's
            // DistantLight::Sample_Li does: one traversal serves every kind of light.
            vec3 far = c.p + d * (2.0 * l.radius);
            y = PathVertex(far, -d, -d, -d, vec3(0.0), 0, 1.0, pdfFresh, 0.0, false, false, 0.0);
        } else {
            d = l.position - c.p;
            float dist2 = dot(d, d);
            if (dist2 == 0.0) return vec3(0.0);
            d *= inversesqrt(dist2);
            Le = punctualIntensity(l, -d);
            if (Le == vec3(0.0)) return vec3(0.0);  // outside a spot's cone
            scale = 1.0 / (dist2 * e.pmf);
            zRevLast = toArea(punctualDirectionPdf(l, -d), l.position, c);
            // On no surface: a zero normal and offset, so the shadow ray ends at the light itself.
            y = PathVertex(l.position, vec3(0.0), vec3(0.0), -d, vec3(0.0), 0, 1.0, pdfFresh, 0.0, false, false, 0.0);
        }
    } else
#endif
    {
        TriangleData tri = e.tri;
        vec2 b = sampleTriangle(e.unitSquare);  // by area: bdpt's vertices carry area densities
        vec3 normal = normalize(cross(tri.e1, tri.e2));
        y = PathVertex(tri.v0 + b.x * tri.e1 + b.y * tri.e2, normal, normal, normal, vec3(0.0), tri.material, 1.0,
                       emitterAreaPdf(tri), 0.0, false, false, surfaceOffset(tri));
        d = y.p - c.p;
        float dist2 = dot(d, d);
        if (dist2 == 0.0) return vec3(0.0);
        d *= inversesqrt(dist2);
        float cosLight = -dot(normal, d);
        if (cosLight <= 0.0) return vec3(0.0);  // one-sided emitter seen from behind
        zRevLast = toArea(cosLight / PI, y.p, c);
        Le = emitterRadiance(e.triangle, tri, b);
        scale = cosLight / (dist2 * y.pdfFwd);
        pdfFresh = y.pdfFwd;
    }
    MaterialData mc = vertexMaterial(true, t - 1);
    vec3 f = vertexBsdf(c, mc, c.wo, d, false);
    if (f == vec3(0.0)) return vec3(0.0);
    float zRevPrev = t >= 3 ? toArea(vertexPdf(c, mc, d, c.wo), c.p, gCamera[t - 2]) : 0.0;
    // (the density of y sampled from c: strategy s = 0, which cannot find a delta light)
    float yRevLast = delta ? 0.0 : toArea(vertexPdf(c, mc, c.wo, d), c.p, y);
    float w = misWeight(1, t, zRevLast, zRevPrev, yRevLast, 0.0, pdfFresh, delta);
    if (!unoccluded(c, y)) return vec3(0.0);
    return c.beta * f * Le * scale * w * spectralFactor(c.dispersive);
}

// Strategy s >= 2: z_{t-1} joined to y_{s-1}: the unweighted contribution
// alpha^L f(y -> z) G(y <-> z) f(z -> y) alpha^E (Veach 1997, section 10.2), the cosines inside the two f
// (see vertexBsdf), so G = V / r^2.
vec3 connectSubpaths(int s, int t) {
    PathVertex c = gCamera[t - 1], l = gLight[s - 1];
    MaterialData ml = vertexMaterial(false, s - 1);
    if (isDeltaOnly(ml)) return vec3(0.0);
    vec3 d = l.p - c.p;
    float dist2 = dot(d, d);
    if (dist2 == 0.0) return vec3(0.0);
    d *= inversesqrt(dist2);
    MaterialData mc = vertexMaterial(true, t - 1);
    vec3 fc = vertexBsdf(c, mc, c.wo, d, false);
    if (fc == vec3(0.0)) return vec3(0.0);
    vec3 fl = vertexBsdf(l, ml, l.wo, -d, true);
    if (fl == vec3(0.0)) return vec3(0.0);
    float zRevLast = toArea(vertexPdf(l, ml, l.wo, -d), l.p, c);
    float zRevPrev = t >= 3 ? toArea(vertexPdf(c, mc, d, c.wo), c.p, gCamera[t - 2]) : 0.0;
    float yRevLast = toArea(vertexPdf(c, mc, c.wo, d), c.p, l);
    float yRevPrev = toArea(vertexPdf(l, ml, -d, l.wo), l.p, gLight[s - 2]);
    float w = misWeight(s, t, zRevLast, zRevPrev, yRevLast, yRevPrev, 0.0, gLightPunctual);
    if (!unoccluded(c, l)) return vec3(0.0);
    return c.beta * fc * fl * l.beta / dist2 * w * spectralFactor(c.dispersive || l.dispersive);
}

// The camera subpath, evaluating every strategy (s, t) as its vertex z_{t-1} is found: the estimator
// F = sum over s, t of w_{s,t} C*_{s,t} (Veach 1997, section 10.2).
vec3 radiance(Ray ray) {
    int maxDepth = min(uMaxDepth, BDPT_MAX_DEPTH);
    gSpectralWeight = vec3(1.0);
    int lightVertices = traceLightSubpathFor(gRngPixel, gRngSample, maxDepth);

    storeCameraVertex(0, PathVertex(ray.origin, ray.dir, ray.dir, ray.dir, vec3(1.0), 0, 1.0, 1.0, 0.0, false, false, 0.0));
    vec3 L = vec3(0.0), beta = vec3(1.0);
    float etaScale = 1.0;  // for the roulette (survivesRoulette)
    float pdfDir = 1.0;  // solid-angle density of the direction that led here (the camera's is not needed)
    bool dispersive = false;
    for (int depth = 0;; ++depth) {
        int t = depth + 2;  // this hit is z_{t-1}
        Hit hit;
        if (!traceClosest(ray, hit)) {
            // Only s = 0 finds the environment here (see the header): full weight.
            L += beta * environmentRadiance(ray.dir) * spectralFactor(dispersive);
            break;
        }
        Surface s = surfaceAt(ray, hit);
        dispersive = meetDispersion(s) || dispersive;
        absorbInside(s, hit.t, beta);
        PathVertex z = PathVertex(s.position, s.geometricNormal, storedNormal(s), -ray.dir, beta, s.materialIndex,
                                  s.eta, 1.0, 0.0, false, dispersive, s.offset);
        // z_1's density is the camera's (its direction spread over the film), for strategy t = 1.
        z.pdfFwd = toArea(t >= 3 ? pdfDir : cameraDirectionPdf(ray.dir), gCamera[t - 2].p, z);
        storeCameraVertex(t - 1, z);
#if defined(NORMAL_MAPPED_SURFACES) && !CAUSTICS_LIGHT_TRACED
        gCameraBent[t - 1] = false;  // (set below once its direction is sampled; joins here scatter off no delta)
#endif
        keepDiffuse(true, t - 1, s);

        // s = 0: the camera subpath hit an emitter.
        vec3 Le = emittedRadiance(s);
        if (Le != vec3(0.0)) {
            float zRevPrev = t >= 3 ? toArea(dot(s.geometricNormal, z.wo) / PI, z.p, gCamera[t - 2]) : 0.0;
            // An emitter whose selection probability rounds to 0 (lights.glsl) starts no light subpath:
            // s = 0 is the only strategy that finds it, with full weight (misWeight would read the 0 as
            // a delta density).
            float emitterPdf = emitterAreaPdf(fetchTriangle(hit.triangle));
            float w = emitterPdf > 0.0 ? misWeight(0, t, emitterPdf, zRevPrev, 0.0, 0.0, 0.0, false) : 1.0;
            L += beta * Le * w * spectralFactor(dispersive);
        }
        if (depth >= maxDepth) break;

        vec3 wo = toLocal(s, -ray.dir);
        if (wo.z <= 0.0) break;  // -ray.dir disagrees with the shading normal: f = 0 (see the header)
        if (!isDeltaOnly(s.material) && uLightCount > 0) {
            L += connectToLight(t);
            int sMax = min(lightVertices, maxDepth - depth);  // s + t <= maxDepth + 2
            for (int sl = 2; sl <= sMax; ++sl) L += connectSubpaths(sl, t);
        }

        BsdfSample bs;
        BounceNumbers u = drawBounceNumbers(depth);
        if (!sampleVertex(s, z, -ray.dir, u.bsdf, false, bs)) break;
        vec3 dir = toWorld(s, bs.wi);
        if (!(mixedSampling(s) && !bs.delta) && !sameSide(s, bs.wi, dir)) break;
        beta *= bs.weight;
        etaScale *= refractionScale(bs, s);
#if defined(NORMAL_MAPPED_SURFACES) && !CAUSTICS_LIGHT_TRACED
        gCameraBent[t - 1] = bs.delta && bentDelta(s, -ray.dir, dir);
#endif
        if (bs.delta) {
            gCamera[t - 1].delta = true;
            if (t >= 3) gCamera[t - 2].pdfRev = 0.0;
            pdfDir = 0.0;
        } else {
            if (t >= 3) gCamera[t - 2].pdfRev = toArea(vertexPdf(z, s.material, dir, -ray.dir), z.p, gCamera[t - 2]);
            pdfDir = bs.pdf;
        }
        if (!survivesRoulette(beta, etaScale, bs.delta, depth, u.roulette)) break;
        ray = spawnRay(s, dir);
    }
    return L;
}
