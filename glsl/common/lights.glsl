// Light sampling for next-event estimation: the environment, or an emissive triangle picked with
// probability proportional to its power (a CDF in the lights buffer) and a point uniformly on its area.
// Area densities become solid-angle densities at the receiving point through
// d(omega) = cos(theta_light) dA / distance^2, so pdf = pmf / area * distance^2 / cos(theta_light).
uniform vec3 uEnvironment;  // constant radiance arriving from every direction no surface blocks

struct LightSample {
    vec3 dir;       // unit, from the receiving point to the light
    float dist;     // INF for the environment
    vec3 radiance;  // Le arriving along -dir (0 when the back of the emitter faces the point)
    float pdf;      // solid-angle density of choosing dir
    vec3 point;     // on an emitter: the point sampled, its emitting side's unit normal and its offset
    vec3 normal;
    float offset;
};

// The share of light samples that go to the environment: half when there are also emitters.
float environmentSelection() {
#if ENVIRONMENT_MAP == 0
    if (uEnvironment == vec3(0.0)) return 0.0;
#endif
    return uLightCount > 0 ? 0.5 : 1.0;
}

#if ENVIRONMENT_MAP
// An equirectangular map (layout in src/pack/layout.h), importance-sampled texel by texel with the
// probability of luminance * sin(theta), then uniformly inside the texel in (u, v). A texel spans the
// solid angle 2 pi^2 sin(theta) du dv, which converts the density (as pbrt-v4 does for image infinite lights).
// Read as images or texel fetches like the scene buffers (scene_data.glsl). The map's size is the define
// ENVIRONMENT_SIZE (an ivec2): a constant costs fewer instructions than a uniform or textureSize, and
// an image's imageSize would need GL_ARB_shader_image_size (docs/optimisation-log.md, entry 31).
#ifdef SCENE_READS_IMAGES
layout(rgba32f) readonly uniform image2D uEnvironmentMap;
layout(r32f) readonly uniform imageBuffer uEnvironmentCdf;
#else
uniform sampler2D uEnvironmentMap;
uniform samplerBuffer uEnvironmentCdf;
#endif
uniform float uEnvironmentRotation;  // radians about +y

vec3 environmentMapTexel(ivec2 p) { return SCENE_TEXEL_2D(uEnvironmentMap, p).rgb; }
float environmentCdfTexel(int i) { return SCENE_TEXEL(uEnvironmentCdf, i).r; }

vec3 rotateY(vec3 d, float angle) {
    float c = cos(angle), s = sin(angle);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

vec2 directionToUv(vec3 d) {
    d = rotateY(d, -uEnvironmentRotation);
    return vec2(0.5 + atan(d.x, -d.z) / (2.0 * PI), acos(clamp(d.y, -1.0, 1.0)) / PI);
}

vec3 uvToDirection(vec2 uv) {
    float phi = (uv.x - 0.5) * 2.0 * PI, theta = uv.y * PI;
    return rotateY(vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi)), uEnvironmentRotation);
}

ivec2 environmentTexel(vec2 uv) {
    return clamp(ivec2(uv * vec2(ENVIRONMENT_SIZE)), ivec2(0), ENVIRONMENT_SIZE - 1);
}

vec3 environmentRadiance(vec3 dir) { return environmentMapTexel(environmentTexel(directionToUv(dir))); }

float cdfAt(int i) { return i < 0 ? 0.0 : environmentCdfTexel(i); }

// First index in [first, first + count) whose cdf exceeds u.
int searchCdf(int first, int count, float u) {
    int lo = first, hi = first + count - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (environmentCdfTexel(mid) <= u) lo = mid + 1;
        else hi = mid;
    }
    return lo - first;
}

float environmentPdf(vec3 dir) {
    vec2 uv = directionToUv(dir);
    ivec2 size = ENVIRONMENT_SIZE, t = environmentTexel(uv);
    float rowPmf = cdfAt(t.y) - cdfAt(t.y - 1);
    int row = size.y + t.y * size.x;
    float texelPmf = rowPmf * (cdfAt(row + t.x) - (t.x == 0 ? 0.0 : cdfAt(row + t.x - 1)));
    float sinTheta = sin(uv.y * PI);
    if (sinTheta <= 0.0) return 0.0;
    return environmentSelection() * texelPmf * float(size.x * size.y) / (2.0 * PI * PI * sinTheta);
}

// One 2D sample for the whole choice: u.x picks the row and u.y the texel in it, and each, rescaled to
// the picked entry's share, places the point inside the texel (as sampleEmitterPoint reuses the
// emitter pick's number): the pick's strata and the point's go together, where three pairs would pair
// them at random, and with the blue-noise sampler the same way in every pixel.
vec3 sampleEnvironmentDirection() {
    ivec2 size = ENVIRONMENT_SIZE;
    vec2 u = rand2();
    int y = searchCdf(0, size.y, u.x);
    float below = cdfAt(y - 1);
    float inRow = clamp((u.x - below) / (cdfAt(y) - below), 0.0, 0.99999994);
    int row = size.y + y * size.x;
    int x = searchCdf(row, size.x, u.y);
    float left = x == 0 ? 0.0 : cdfAt(row + x - 1);
    float inTexel = clamp((u.y - left) / (cdfAt(row + x) - left), 0.0, 0.99999994);
    return uvToDirection((vec2(x, y) + vec2(inTexel, inRow)) / vec2(size));
}
#else
vec3 environmentRadiance(vec3 dir) { return uEnvironment; }

// Uniform over the sphere for a constant environment.
float environmentPdf(vec3 dir) { return environmentSelection() / (4.0 * PI); }

vec3 sampleEnvironmentDirection() { return sampleUniformSphere(rand2()); }
#endif

int pickLight(float u) {
    int lo = 0, hi = uLightCount - 1;
    while (lo < hi) {  // first entry whose cdf exceeds u
        int mid = (lo + hi) / 2;
        if (lightTexel(mid).y <= u) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

// An emitter triangle picked by power and a point of the unit square for the point on it, from one 2D sample:
// x picks by the cdf and, rescaled to the picked entry's share of [0, 1), places the point with y
// (the reuse of a light pick's number that Cycles and pbrt make too). One stratified 2D point then
// spreads over all the emitters' area, where a pick and a point from two pairs would pair them at
// random, and (with the blue-noise sampler, rng.glsl) the same way in every pixel. The pick is exact:
// the cdf lies on rand()'s 2^-24 grid and the picked entry's bounds differ by its pmf exactly. The
// rescaled x keeps pmf * 2^24 levels; below 2^-12 of the power (fewer than 4096 levels across the
// triangle) the point takes a pair of its own.
struct EmitterPoint {
    TriangleData tri;
    vec2 unitSquare;  // for the point on it: sampleTriangle (uniform by area) or sampleSphericalTriangle
    int triangle;     // tri's index
};

EmitterPoint sampleEmitterPoint() {
    vec2 u = rand2();
    int entry = pickLight(u.x);
    int triangle = int(lightTexel(entry).x);
    TriangleData tri = fetchTriangle(triangle);
    float below = entry > 0 ? lightTexel(entry - 1).y : 0.0;
    vec2 v = tri.lightPmf >= 1.0 / 4096.0 ? vec2((u.x - below) / tri.lightPmf, u.y) : rand2();
    return EmitterPoint(tri, v, triangle);
}

// The radiance leaving the front of emitter triangle i at barycentrics b: Ke, times its emission map,
// times its coverage (opacity.glsl: an emitter with alpha emits only where it covers, as rays see it
// only there; for BLEND the expected coverage alpha). Without maps or alpha, Ke alone.
vec3 emitterRadiance(int i, TriangleData tri, vec2 b) {
    vec3 Le = materialEmission(tri.material);
#ifdef SURFACE_TEXTURES
#if HAS_MAP(EMISSION_MAP_BIT)
    int t = materialMaps(tri.material).z;
    if (t >= 0) Le *= sampleTexture(t, fetchTexcoord(i, b));
#endif
#endif
#ifdef SURFACE_OPACITY
    if ((int(tri.flags) & TRIANGLE_ALPHA_FLAG) != 0) Le *= materialCoverage(tri.material, i, b);
#endif
    return Le;
}

// The barycentrics (of v1 and v2) of point p in tri's plane.
vec2 barycentricsOf(TriangleData tri, vec3 p) {
    vec3 d = p - tri.v0;
    float d00 = dot(tri.e1, tri.e1), d01 = dot(tri.e1, tri.e2), d11 = dot(tri.e2, tri.e2);
    float d20 = dot(d, tri.e1), d21 = dot(d, tri.e2);
    float det = d00 * d11 - d01 * d01;
    return vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / det;
}

// The area density of sampleLight's emitter points on triangle tri: its pmf (the probability that
// pickLight returns it: the packer stores the cdf on a 2^-24 grid, the resolution of rand(), and the pmf
// as the exact difference of two entries, pack/pack.cpp) over its area. Every estimator that needs the
// density of an emitter point reads it from here, so sampling and MIS weights agree to the last bit.
float emitterAreaPdf(TriangleData tri) { return tri.lightPmf / (0.5 * length(cross(tri.e1, tri.e2))); }

// Emitters that subtend more than kMinSphericalArea steradians from the shading point are sampled
// uniformly in solid angle (sampleSphericalTriangle): that removes the 1 / r^2 and the emitter's cosine
// from the estimate, what area sampling leaves noisy next to a large or near light. Below it the two
// densities differ by about the solid angle itself (r^2 / cos varies over the emitter by that share), so
// area sampling is as good and cheaper; 0.1 sr is where the difference starts to show (the Cornell box's
// lamp, 0.05 sr from its floor, renders the same either way: BENCHMARKS.md, "Samplers"). Beyond
// kMaxSphericalArea (nearly a hemisphere) the spherical triangle is ill-conditioned (pbrt-v4's bound).
// SPHERICAL_LIGHT_SAMPLING (set by the renderer from RenderSettings::lightSampling: --light-sampling
// auto chooses it for scenes with an emitter close to a surface it faces, pack/light_strategy.h): 1
// samples as above, 0 always by area (the spherical code costs registers even where no emitter is
// large enough to take it).
#ifndef SPHERICAL_LIGHT_SAMPLING
#define SPHERICAL_LIGHT_SAMPLING 0
#endif
const float kMinSphericalArea = 0.1, kMaxSphericalArea = 6.22;

// The solid angle of triangle tri seen from `from`, or 0 when sampleLight samples it by area (small,
// too large, or seen from behind: one-sided emitters). The choice is a function of (tri, from) alone,
// so lightPdf makes the same one. A cheap estimate (area x cos / d^2 at the centroid) decides first;
// the exact solid angle is computed only for the emitters it sends to spherical sampling.
float sphericalSamplingArea(TriangleData tri, vec3 from) {
#if SPHERICAL_LIGHT_SAMPLING
    vec3 n = cross(tri.e1, tri.e2);                             // twice the area, along the normal
    vec3 c = tri.v0 + (tri.e1 + tri.e2) * (1.0 / 3.0) - from;  // to the centroid
    float facing = -dot(n, c);
    float d2 = dot(c, c);
    if (facing <= 0.0 || facing < 2.0 * kMinSphericalArea * d2 * sqrt(d2)) return 0.0;
    vec3 a = tri.v0 - from;
    float area = sphericalTriangleArea(normalize(a), normalize(a + tri.e1), normalize(a + tri.e2));
    return area > 0.0 && area < kMaxSphericalArea ? area : 0.0;
#else
    return 0.0;
#endif
}

LightSample sampleLight(vec3 from) {
    LightSample ls = LightSample(vec3(0.0, 0.0, 1.0), 0.0, vec3(0.0), 0.0, vec3(0.0), vec3(0.0), 0.0);
    float pEnvironment = environmentSelection();
    if (rand() < pEnvironment) {
        ls.dir = sampleEnvironmentDirection();
        ls.dist = INF;
        ls.radiance = environmentRadiance(ls.dir);
        ls.pdf = environmentPdf(ls.dir);
        return ls;
    }
    if (uLightCount == 0) return ls;
    EmitterPoint e = sampleEmitterPoint();
    TriangleData tri = e.tri;
    ls.normal = normalize(cross(tri.e1, tri.e2));
    ls.offset = surfaceOffset(tri);
    float solidAngle = sphericalSamplingArea(tri, from);
    if (solidAngle > 0.0) {
        vec3 a = tri.v0 - from;
        ls.dir = sampleSphericalTriangle(normalize(a), normalize(a + tri.e1), normalize(a + tri.e2),
                                         e.unitSquare);
        float cosLight = -dot(ls.normal, ls.dir);
        if (cosLight <= 0.0) return ls;
        ls.dist = -dot(a, ls.normal) / cosLight;  // to the emitter's plane along ls.dir
        ls.point = from + ls.dist * ls.dir;
        ls.radiance = emitterRadiance(e.triangle, tri, barycentricsOf(tri, ls.point));
        ls.pdf = (1.0 - pEnvironment) * tri.lightPmf / solidAngle;
        return ls;
    }
    vec2 b = sampleTriangle(e.unitSquare);
    ls.point = tri.v0 + b.x * tri.e1 + b.y * tri.e2;
    vec3 toLight = ls.point - from;
    float dist2 = dot(toLight, toLight);
    ls.dist = sqrt(dist2);
    ls.dir = toLight / ls.dist;
    float cosLight = -dot(ls.normal, ls.dir);
    if (cosLight <= 0.0 || dist2 == 0.0) return ls;  // one-sided emitter seen from behind
    ls.radiance = emitterRadiance(e.triangle, tri, b);
    ls.pdf = (1.0 - pEnvironment) * emitterAreaPdf(tri) * dist2 / cosLight;
    return ls;
}

// Whether nothing blocks the light sample ls from surface point s: offset at both ends for an emitter
// point (ray_offset.glsl), from s to infinity for the environment.
// One call of occluded for both cases: llvmpipe runs every inlined copy of the traversal whenever any
// pixel of its SIMD group needs it, and a second copy cost 20 % of a Cornell box render.
bool lightVisible(Surface s, LightSample ls) {
    Ray ray = spawnRay(s, ls.dir);
    float tMax = INF;
    if (ls.dist < INF &&
        !shadowRayBetween(s.position, s.geometricNormal, s.offset, ls.point, ls.normal, ls.offset, ray, tMax))
        return true;
    return !occluded(ray, tMax);
}

// Solid-angle density with which sampleLight(from) would have chosen the emitter point a ray from
// `from` hit at hit.t.
float lightPdf(vec3 from, Ray ray, Hit hit) {
    TriangleData tri = fetchTriangle(hit.triangle);
    float solidAngle = sphericalSamplingArea(tri, from);
    if (solidAngle > 0.0) return (1.0 - environmentSelection()) * tri.lightPmf / solidAngle;
    float cosLight = abs(dot(normalize(cross(tri.e1, tri.e2)), ray.dir));
    return (1.0 - environmentSelection()) * emitterAreaPdf(tri) * hit.t * hit.t / cosLight;
}
