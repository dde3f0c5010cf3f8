// The seed's estimator, kept as plain as smallpt: at every hit add the emitted light, then continue
// in a direction drawn uniformly over the hemisphere. For a Lambertian surface f = albedo / pi and the
// pdf is 1 / (2 pi), so each bounce weighs f cos(theta) / pdf = 2 * albedo * cos(theta).
vec3 radiance(Ray ray) {
    vec3 L = vec3(0.0), beta = vec3(1.0);
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!traceClosest(ray, hit)) break;
        Surface s = surfaceAt(ray, hit);
        L += beta * emittedRadiance(s);
        if (depth == uMaxDepth) break;
        vec3 dir = sampleUniformHemisphere(s.shadingNormal, rand2());
        if (!leavesSurface(s, dir)) break;
        beta *= 2.0 * materialAlbedo(s.material) * dot(dir, s.shadingNormal);
        if (!survivesRoulette(beta, depth)) break;
        ray = spawnRay(s, dir);
    }
    return L;
}
