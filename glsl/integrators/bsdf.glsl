// BSDF importance sampling: directions drawn with a density shaped like the surface's scattering
// (cos(theta) / pi for a Lambertian surface, so each bounce weighs f cos / pdf = albedo and the cosine
// noise is gone; visible GGX normals for glossy ones; Fresnel-chosen reflection or refraction for glass).
// Light is found only where a path hits it, so punctual lights (point, spot, directional: no size, no
// ray can hit one) do not light this integrator's image; the renderer warns (src/render/renderer.cpp).
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
        BsdfSample bs;
        BounceNumbers u = drawBounceNumbers(depth);
        if (!bsdfSample(s.material, toLocal(s, -ray.dir), u.bsdf, s.eta, bs)) break;
        vec3 dir = toWorld(s, bs.wi);
        if (!sameSide(s, bs.wi, dir)) break;
        beta *= bs.weight;
        etaScale *= refractionScale(bs, s);
        if (!survivesRoulette(beta, etaScale, bs.delta, depth, u.roulette)) break;
        ray = spawnRay(s, dir);
    }
    return L + takeIndirect();
}
