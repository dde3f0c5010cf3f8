// BSDF importance sampling: directions drawn with density cos(theta) / pi, proportional to the
// Lambertian integrand, so each bounce weighs f cos / pdf = albedo and the cosine noise is gone.
vec3 radiance(Ray ray) {
    vec3 L = vec3(0.0), beta = vec3(1.0);
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!traceClosest(ray, hit)) break;
        Surface s = surfaceAt(ray, hit);
        L += beta * emittedRadiance(s);
        if (depth == uMaxDepth) break;
        vec3 dir = sampleCosineHemisphere(s.shadingNormal, rand2());
        if (!leavesSurface(s, dir)) break;
        beta *= materialAlbedo(s.material);
        if (!survivesRoulette(beta, depth)) break;
        ray = spawnRay(s, dir);
    }
    return L;
}
