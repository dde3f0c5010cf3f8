// Light sampling for next-event estimation: the environment, or an emissive triangle picked with
// probability proportional to its power (a CDF in the lights buffer) and a point uniformly on its area.
// Area densities become solid-angle densities at the receiving point through
// d(omega) = cos(theta_light) dA / distance^2, so pdf = pmf / area * distance^2 / cos(theta_light).
uniform vec3 uEnvironment;  // radiance arriving from every direction no surface blocks

struct LightSample {
    vec3 dir;       // unit, from the receiving point to the light
    float dist;     // INF for the environment
    vec3 radiance;  // Le arriving along -dir (0 when the back of the emitter faces the point)
    float pdf;      // solid-angle density of choosing dir
};

vec3 environmentRadiance(vec3 dir) { return uEnvironment; }

// The share of light samples that go to the environment: half when there are also emitters.
float environmentSelection() {
    if (uEnvironment == vec3(0.0)) return 0.0;
    return uLightCount > 0 ? 0.5 : 1.0;
}

// Uniform over the sphere for a constant environment.
float environmentPdf(vec3 dir) { return environmentSelection() / (4.0 * PI); }

int pickLight(float u) {
    int lo = 0, hi = uLightCount - 1;
    while (lo < hi) {  // first entry whose cdf exceeds u
        int mid = (lo + hi) / 2;
        if (texelFetch(uLights, mid).y <= u) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

LightSample sampleLight(vec3 from) {
    LightSample ls = LightSample(vec3(0.0, 0.0, 1.0), 0.0, vec3(0.0), 0.0);
    float u = rand();
    float pEnvironment = environmentSelection();
    if (u < pEnvironment) {
        vec2 v = rand2();
        float z = 1.0 - 2.0 * v.x, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * PI * v.y;
        ls.dir = vec3(r * cos(phi), r * sin(phi), z);
        ls.dist = INF;
        ls.radiance = environmentRadiance(ls.dir);
        ls.pdf = environmentPdf(ls.dir);
        return ls;
    }
    if (uLightCount == 0) return ls;
    vec4 light = texelFetch(uLights, pickLight((u - pEnvironment) / (1.0 - pEnvironment)));
    TriangleData tri = fetchTriangle(int(light.x));
    vec2 b = sampleTriangle(rand2());
    vec3 toLight = tri.v0 + b.x * tri.e1 + b.y * tri.e2 - from;
    float dist2 = dot(toLight, toLight);
    ls.dist = sqrt(dist2);
    ls.dir = toLight / ls.dist;
    float cosLight = -dot(normalize(cross(tri.e1, tri.e2)), ls.dir);
    if (cosLight <= 0.0 || dist2 == 0.0) return ls;  // one-sided emitter seen from behind
    ls.radiance = materialEmission(tri.material);
    ls.pdf = (1.0 - pEnvironment) * light.z / light.w * dist2 / cosLight;
    return ls;
}

// Solid-angle density with which sampleLight would have chosen the emitter point a ray hit at hit.t.
float lightPdf(Ray ray, Hit hit) {
    TriangleData tri = fetchTriangle(hit.triangle);
    vec3 n = cross(tri.e1, tri.e2);
    float area = 0.5 * length(n);
    float cosLight = abs(dot(n, ray.dir)) / (2.0 * area);
    return (1.0 - environmentSelection()) * tri.lightPmf / area * hit.t * hit.t / cosLight;
}
