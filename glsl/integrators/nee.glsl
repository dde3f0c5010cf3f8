// Next-event estimation with multiple importance sampling (Veach 1997, ch. 9): at every vertex a
// light sample and a BSDF sample each estimate direct lighting, and the power heuristic weighs the
// two so that each covers the paths the other samples badly. Emission found by a BSDF-sampled ray
// is weighted against the density light sampling would have had for it.
vec3 radiance(Ray ray) {
    vec3 L = vec3(0.0), beta = vec3(1.0);
    float bsdfPdf = 0.0;  // solid-angle density of the direction that led to this vertex
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!traceClosest(ray, hit)) break;
        Surface s = surfaceAt(ray, hit);
        vec3 Le = emittedRadiance(s);
        if (Le != vec3(0.0)) {
            float weight = depth == 0 ? 1.0 : powerHeuristic(bsdfPdf, lightPdf(ray, hit));
            L += beta * weight * Le;
        }
        if (depth == uMaxDepth) break;

        vec3 albedo = materialAlbedo(s.material);
        LightSample ls = sampleLight(s.position);
        float cosLight = dot(ls.dir, s.shadingNormal);
        if (ls.pdf > 0.0 && cosLight > 0.0 && leavesSurface(s, ls.dir) &&
            !occluded(spawnRay(s, ls.dir), ls.dist * (1.0 - 1e-4))) {
            vec3 f = albedo / PI;
            L += beta * f * cosLight * ls.radiance * powerHeuristic(ls.pdf, cosLight / PI) / ls.pdf;
        }

        vec3 dir = sampleCosineHemisphere(s.shadingNormal, rand2());
        if (!leavesSurface(s, dir)) break;
        bsdfPdf = dot(dir, s.shadingNormal) / PI;
        beta *= albedo;
        if (!survivesRoulette(beta, depth)) break;
        ray = spawnRay(s, dir);
    }
    return L;
}
