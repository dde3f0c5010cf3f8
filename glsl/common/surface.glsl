// What an integrator needs to know about the point a ray hit.
uniform float uRayOffset;  // self-intersection offset along the normal, scaled to the scene's size

struct Surface {
    vec3 position;
    vec3 geometricNormal;  // unit, on the side the ray came from
    vec3 shadingNormal;    // unit, interpolated from the vertices, on the same side
    int material;
    bool frontFace;        // the ray hit the counter-clockwise side: the side that emits
};

Surface surfaceAt(Ray ray, Hit hit) {
    TriangleData tri = fetchTriangle(hit.triangle);
    Surface s;
    s.position = ray.origin + hit.t * ray.dir;
    vec3 n = normalize(cross(tri.e1, tri.e2));
    s.frontFace = dot(n, ray.dir) < 0.0;
    s.geometricNormal = s.frontFace ? n : -n;
    vec3 ns = fetchShadingNormal(hit.triangle, hit.uv);
    s.shadingNormal = dot(ns, s.geometricNormal) < 0.0 ? -ns : ns;
    s.material = tri.material;
    return s;
}

vec3 emittedRadiance(Surface s) { return s.frontFace ? materialEmission(s.material) : vec3(0.0); }

// A ray leaving the surface, nudged off it to the side it leaves on.
Ray spawnRay(Surface s, vec3 dir) {
    float side = dot(dir, s.geometricNormal) >= 0.0 ? 1.0 : -1.0;
    return Ray(s.position + side * uRayOffset * s.geometricNormal, dir);
}

// A sampled direction under the geometric surface cannot leave it (shading normals can ask for one).
bool leavesSurface(Surface s, vec3 dir) { return dot(dir, s.geometricNormal) > 0.0; }

// Russian roulette (as in pbrt-v4 PathIntegrator::Li): after a few bounces, stop a path with probability
// 1 - max(beta) and reweight the survivors, which keeps the estimate unbiased.
int gBounces = 0;  // bounces the current path survived, for the bounces view

bool survivesRoulette(inout vec3 beta, int depth) {
    if (depth >= 3) {
        float keep = min(1.0, max(beta.r, max(beta.g, beta.b)));
        if (rand() >= keep) return false;
        beta /= keep;
    }
    ++gBounces;
    return true;
}
