// The seed's estimator, kept as plain as smallpt: at every hit add the emitted light, then continue
// in a direction drawn uniformly over the hemisphere. For a Lambertian surface f = albedo / pi and the
// pdf is 1 / (2 pi), so each bounce weighs f cos(theta) / pdf = 2 * albedo * cos(theta).
// Uniform directions cannot find a mirror's or a glass's single direction, so those surfaces (and the
// other non-Lambertian ones) are sampled by their BSDF instead.
#include "common/sampling.glsl"
#include "common/intersect.glsl"
#include "common/bsdf.glsl"
#include "common/surface.glsl"
#include "common/lights.glsl"
#include "common/render_uniforms.glsl"

vec3 radiance(Ray ray) {
    vec3 L = vec3(0.0), beta = vec3(1.0);
    float etaScale = 1.0;  // for the roulette (survivesRoulette)
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!traceClosest(ray, hit)) {
            addLight(L, beta * environmentRadiance(ray.dir), depth);
            break;
        }
        Surface s = surfaceAt(ray, hit);
        applyDispersion(s, beta);
        absorbInside(s, hit.t, beta);
        addLight(L, beta * emittedRadiance(s), depth);
        if (depth == uMaxDepth) break;
        // The view direction below the shading normal: f = 0, as in the other integrators.
        if (dot(-ray.dir, s.shadingNormal) <= 0.0) break;
        vec3 dir;
        bool delta = false;
        BounceNumbers u = drawBounceNumbers(depth);
        if (s.material.type == MATERIAL_DIFFUSE) {
            dir = sampleUniformHemisphere(s.shadingNormal, u.bsdf.xy);
            if (dot(dir, s.geometricNormal) <= 0.0) break;
            beta *= 2.0 * s.material.diffuse * dot(dir, s.shadingNormal);
        } else {
            BsdfSample bs;
            if (!bsdfSample(s.material, toLocal(s, -ray.dir), u.bsdf, s.eta, bs)) break;
            dir = toWorld(s, bs.wi);
            if (!sameSide(s, bs.wi, dir)) break;
            beta *= bs.weight;
            etaScale *= refractionScale(bs, s);
            delta = bs.delta;
        }
        if (!survivesRoulette(beta, etaScale, delta, depth, u.roulette)) break;
        ray = spawnRay(s, dir);
    }
    // Light is found only where a path hits it, so point, spot and directional lights, which nothing can
    // hit, do not light this image (as in bsdf.glsl; the renderer warns).
    return L + takeIndirect();
}
