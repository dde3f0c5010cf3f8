// Light sampling for next-event estimation: the environment, or an emissive triangle or punctual light
// picked with probability proportional to its power (a CDF in the lights buffer, src/pack/layout.h) or,
// with LIGHT_TREE, by the light tree (light_tree.glsl) and, on a triangle, a point uniformly on its area
// (or in the solid angle it subtends, below). Area densities become solid-angle densities at the
// receiving point through d(omega) = cos(theta_light) dA / distance^2, so pdf = pmf / area * distance^2 /
// cos(theta_light). A punctual light (point, spot, directional: src/scene/scene.h) is a delta
// distribution: it has one direction toward the receiving point, which only light sampling finds.
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/textures.glsl"
#include "common/intersect.glsl"
#include "common/opacity.glsl"
#include "common/ray_offset.glsl"
#include "common/surface.glsl"

uniform vec3 uEnvironment;  // constant radiance arriving from every direction no surface blocks

#include "common/light_tree.glsl"  // with LIGHT_TREE

struct LightSample {
    vec3 dir;       // unit, from the receiving point to the light
    float dist;     // INF for the environment and a directional light
    vec3 radiance;  // Le arriving along -dir (0 when the back of the emitter faces the point); for a
                    // delta light the irradiance it gives a surface facing it: I / r^2, or E
    float pdf;      // solid-angle density of choosing dir; for a delta light the probability of the pick
    vec3 point;     // on an emitter: the point sampled, its emitting side's unit normal and its offset
    vec3 normal;    // (a point or spot light: its position, a zero normal and offset)
    float offset;
    bool delta;     // a punctual light: no BSDF sample can find it, so no MIS (weight 1)
};

// Punctual lights, compiled in only for scenes that have some (the renderer sets PUNCTUAL_LIGHTS). Their
// cdf entries follow the emitter triangles' (index -1 - k for light k), and their data follows the cdf
// (src/pack/layout.h).
#ifndef PUNCTUAL_LIGHTS
#define PUNCTUAL_LIGHTS 0
#endif
#if PUNCTUAL_LIGHTS
const int PUNCTUAL_POINT = 0, PUNCTUAL_SPOT = 1, PUNCTUAL_DIRECTIONAL = 2;  // fp::PunctualLightType

struct PunctualLight {
    int type;
    vec3 position;   // point, spot; directional: the centre of the sphere its light subpaths start from
    vec3 direction;  // unit, the way the light travels (spot: the cone's axis)
    vec3 intensity;  // W/sr; directional: the irradiance in W/m^2 on a surface facing it
    float cosOuter, cosInner;  // spot
    float radius;              // directional: the sphere's radius
};

PunctualLight fetchPunctualLight(int k) {
    int i = uLightCount + k * PUNCTUAL_TEXELS;
    vec4 a = lightTexel(i), b = lightTexel(i + 1), c = lightTexel(i + 2);
    return PunctualLight(int(a.w), a.xyz, b.xyz, c.rgb, b.w, c.w, b.w);
}

// Radiant intensity of a point or spot light along unit direction w (away from the light): a spot
// scales it by glTF's falloff t^2, t the cosine's linear ramp from the outer cone (0) to the inner one
// (1) (src/scene/punctual_light.h spotFalloff).
vec3 punctualIntensity(PunctualLight l, vec3 w) {
    if (l.type != PUNCTUAL_SPOT) return l.intensity;
    float t = clamp((dot(l.direction, w) - l.cosOuter) / (l.cosInner - l.cosOuter), 0.0, 1.0);
    return l.intensity * (t * t);
}

// The directions bdpt's light subpaths leave a point or spot light in (pbrt-v4 PointLight::SampleLe,
// SpotLight::SampleLe): uniform over the sphere, or uniform inside a spot's outer cone; and their
// solid-angle density.
vec3 samplePunctualDirection(PunctualLight l, vec2 u) {
    if (l.type == PUNCTUAL_POINT) return sampleUniformSphere(u);
    return sampleUniformCone(l.direction, l.cosOuter, u);
}

float punctualDirectionPdf(PunctualLight l, vec3 w) {
    if (l.type == PUNCTUAL_POINT) return 1.0 / (4.0 * PI);
    return dot(l.direction, w) >= l.cosOuter ? 1.0 / (2.0 * PI * (1.0 - l.cosOuter)) : 0.0;
}
#endif

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

// The density in solid angle of a direction in texel t at polar angle theta (the choice of the
// environment included).
float environmentTexelPdf(ivec2 t, float sinTheta) {
    if (sinTheta <= 0.0) return 0.0;
    ivec2 size = ENVIRONMENT_SIZE;
    float rowPmf = cdfAt(t.y) - cdfAt(t.y - 1);
    int row = size.y + t.y * size.x;
    float texelPmf = rowPmf * (cdfAt(row + t.x) - (t.x == 0 ? 0.0 : cdfAt(row + t.x - 1)));
    return environmentSelection() * texelPmf * float(size.x * size.y) / (2.0 * PI * PI * sinTheta);
}

float environmentPdf(vec3 dir) {
    vec2 uv = directionToUv(dir);
    return environmentTexelPdf(environmentTexel(uv), sin(uv.y * PI));
}

// One 2D sample for the whole choice: u.x picks the row and u.y the texel in it, and each, rescaled to
// the picked entry's share, places the point inside the texel (as sampleEmitterPoint reuses the
// emitter pick's number): the pick's strata and the point's go together, where three pairs would pair
// them at random, and with the blue-noise sampler the same way in every pixel. The picked texel's
// radiance and density go with the direction: found again from the direction (uvToDirection, then
// directionToUv, in float on llvmpipe) the texel is a neighbour for about 0.4 % of the samples of a
// 1024 x 512 map, whose density and MIS weight then belong to the neighbour; under a small bright sun
// (a dim neighbour, a small weight) that lost 0.4 % of the sun's light (tools/race_cycles.py
// --analytic, the plane under a sky).
vec3 sampleEnvironment(out vec3 radiance, out float pdf) {
    ivec2 size = ENVIRONMENT_SIZE;
    vec2 u = rand2();
    int y = searchCdf(0, size.y, u.x);
    float below = cdfAt(y - 1);
    float inRow = clamp((u.x - below) / (cdfAt(y) - below), 0.0, 0.99999994);
    int row = size.y + y * size.x;
    int x = searchCdf(row, size.x, u.y);
    float left = x == 0 ? 0.0 : cdfAt(row + x - 1);
    float inTexel = clamp((u.y - left) / (cdfAt(row + x) - left), 0.0, 0.99999994);
    vec2 uv = (vec2(x, y) + vec2(inTexel, inRow)) / vec2(size);
    radiance = environmentMapTexel(ivec2(x, y));
    pdf = environmentTexelPdf(ivec2(x, y), sin(uv.y * PI));
    return uvToDirection(uv);
}
#else
vec3 environmentRadiance(vec3 dir) { return uEnvironment; }

// Uniform over the sphere for a constant environment.
float environmentPdf(vec3 dir) { return environmentSelection() / (4.0 * PI); }

vec3 sampleEnvironment(out vec3 radiance, out float pdf) {
    radiance = uEnvironment;
    pdf = environmentSelection() / (4.0 * PI);
    return sampleUniformSphere(rand2());
}
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
// A punctual light's entry (scenes with PUNCTUAL_LIGHTS) is picked the same way and takes no point.
struct EmitterPoint {
    TriangleData tri;
    vec2 unitSquare;  // for the point on it: sampleTriangle (uniform by area) or sampleSphericalTriangle
    int triangle;     // tri's index (when punctual is -1)
    int punctual;     // -1: the emitter triangle `tri`; else the punctual light of that number (no tri)
    float pmf;          // its selection probability
};

EmitterPoint sampleEmitterPoint() {
    vec2 u = rand2();
    int entry = pickLight(u.x);
    vec4 texel = lightTexel(entry);
#if PUNCTUAL_LIGHTS
    if (texel.x < 0.0)
        return EmitterPoint(TriangleData(vec3(0.0), vec3(0.0), vec3(0.0), 0, 0.0, 0.0), u, -1, int(-texel.x) - 1, texel.z);
#endif
    int triangle = int(texel.x);
    TriangleData tri = fetchTriangle(triangle);
    float below = entry > 0 ? lightTexel(entry - 1).y : 0.0;
    vec2 v = tri.lightPmf >= 1.0 / 4096.0 ? vec2((u.x - below) / tri.lightPmf, u.y) : rand2();
    return EmitterPoint(tri, v, triangle, -1, tri.lightPmf);
}

#if LIGHT_TREE
#if PUNCTUAL_LIGHTS
#error "the light tree does not bound punctual lights (src/pack/pack.cpp packs none for such scenes)"
#endif
// As sampleEmitterPoint, but the emitter chosen by the light tree for point p of normal n (one 2D sample
// again: x descends the tree, rescaled at each level, and places the point with y). triangle -1: no
// emitter can light p.
EmitterPoint sampleEmitterPointFor(vec3 p, vec3 n) {
    vec2 u = rand2();
    float pmf;
    int entry = pickLightTree(p, n, u.x, pmf);
    if (pmf == 0.0) return EmitterPoint(TriangleData(vec3(0.0), vec3(0.0), vec3(0.0), 0, 0.0, 0.0), u, -1, -1, 0.0);
    int triangle = int(lightTexel(entry).x);
    TriangleData tri = fetchTriangle(triangle);
    return EmitterPoint(tri, pmf >= 1.0 / 4096.0 ? u : rand2(), triangle, -1, pmf);
}
#endif

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
// With the light tree (light_tree.glsl) the probability of the pick depends on the shading point: pmf.
float emitterAreaPdf(TriangleData tri, float pmf) { return pmf / (0.5 * length(cross(tri.e1, tri.e2))); }
float emitterAreaPdf(TriangleData tri) { return emitterAreaPdf(tri, tri.lightPmf); }

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

// A light sample for point `from` of normal `normal` (which only the light tree reads).
LightSample sampleLight(vec3 from, vec3 normal) {
    LightSample ls = LightSample(vec3(0.0, 0.0, 1.0), 0.0, vec3(0.0), 0.0, vec3(0.0), vec3(0.0), 0.0, false);
    // The choice between the environment and the emitters draws a number only when there is one to make.
    float pEnvironment = environmentSelection();
    if (pEnvironment > 0.0 && (pEnvironment >= 1.0 || rand() < pEnvironment)) {
        ls.dir = sampleEnvironment(ls.radiance, ls.pdf);
        ls.dist = INF;
        return ls;
    }
    if (uLightCount == 0) return ls;
#if LIGHT_TREE
    EmitterPoint e = sampleEmitterPointFor(from, normal);
    if (e.triangle < 0) return ls;
#else
    EmitterPoint e = sampleEmitterPoint();
#endif
#if PUNCTUAL_LIGHTS
    // A delta light: the one direction toward it, the irradiance it gives a surface facing it, and the
    // probability of the pick for a "density" (pbrt-v4 section 12.2, PointLight::SampleLi: a delta
    // distribution's pdf is 1; the light sampler's pmf divides, section 13.4).
    if (e.punctual >= 0) {
        PunctualLight l = fetchPunctualLight(e.punctual);
        ls.delta = true;
        if (l.type == PUNCTUAL_DIRECTIONAL) {
            ls.dir = -l.direction;
            ls.dist = INF;
            ls.radiance = l.intensity;
        } else {
            vec3 toLight = l.position - from;
            float dist2 = dot(toLight, toLight);
            if (dist2 == 0.0) return ls;
            ls.dist = sqrt(dist2);
            ls.dir = toLight / ls.dist;
            ls.point = l.position;  // on no surface: normal and offset 0, the shadow ray ends there
            ls.radiance = punctualIntensity(l, -ls.dir) / dist2;
            if (ls.radiance == vec3(0.0)) return ls;  // outside a spot's cone: pdf 0, no shadow ray
        }
        ls.pdf = (1.0 - pEnvironment) * e.pmf;
        return ls;
    }
#endif
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
        ls.pdf = (1.0 - pEnvironment) * e.pmf / solidAngle;
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
    ls.pdf = (1.0 - pEnvironment) * emitterAreaPdf(tri, e.pmf) * dist2 / cosLight;
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

// Solid-angle density with which sampleLight(from, normal) would have chosen the emitter point a ray
// leaving `from` (from its offset point, ray_offset.glsl) hit at hit.t.
float lightPdf(vec3 from, vec3 normal, Ray ray, Hit hit) {
    TriangleData tri = fetchTriangle(hit.triangle);
#if LIGHT_TREE
    // (An emitter whose power pmf rounded to 0 has no entry, and no tree picks it.)
    float pick = tri.lightPmf > 0.0 ? lightTreePmf(from, normal, lightEntryOf(hit.triangle)) : 0.0;
#else
    float pick = tri.lightPmf;
#endif
    float solidAngle = sphericalSamplingArea(tri, from);
    if (solidAngle > 0.0) return (1.0 - environmentSelection()) * pick / solidAngle;
    // Distance and cosine from `from` itself, as sampleLight measures them: the ray left from `from`
    // moved off its surface (ray_offset.glsl), and hit.t, shorter by up to that offset, gave the path a
    // smaller light density than sampleLight's, so that the two MIS weights of a path summed to more
    // than 1 (issue 35: +0.011 % under a lamp 1 above a floor 40 wide, whose offset is 2.3e-4).
    vec3 toLight = ray.origin + hit.t * ray.dir - from;
    float dist2 = dot(toLight, toLight);
    float cosLight = abs(dot(normalize(cross(tri.e1, tri.e2)), toLight)) * inversesqrt(dist2);
    return (1.0 - environmentSelection()) * emitterAreaPdf(tri, pick) * dist2 / cosLight;
}
