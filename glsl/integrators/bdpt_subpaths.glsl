// The pieces of bidirectional path tracing that both of its passes use: the path vertex, BSDF and
// density evaluation at a vertex, the MIS weight over every strategy, and the light subpath. The camera
// pass (integrators/bdpt.glsl) joins camera vertices to it; the light-tracing pass
// (passes/light_trace.frag.glsl) joins its vertices to the camera. Both trace the same light subpath for
// sample k of pixel p (traceLightSubpathFor), so each sample's light subpath serves every strategy, as
// in pbrt-v3 (section 16.3). See bdpt.glsl for the strategies and the limits below.
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/textures.glsl"
#include "common/intersect.glsl"
#include "common/bsdf.glsl"
#include "common/valid_reflection.glsl"
#include "common/ray_offset.glsl"
#include "common/surface.glsl"
#include "common/lights.glsl"
#include "common/caustic_casters.glsl"
#include "common/render_uniforms.glsl"

// Light subpath vertices stored: bdpt's y0 .. y3 (bdpt.glsl), and in nee's light pass (CAUSTICS_LIGHT_TRACED)
// LIGHT_RECORDS, two more, for light that goes through a glass ball (two delta vertices), reaches the
// floor and bounces on CAUSTIC_SMOOTH_BOUNCES - 1 times (causticStrategy). LIGHT_RECORDS, the light
// image's records per path, is set by the renderer (src/render/light_splat.h).
#ifndef LIGHT_RECORDS
#error "LIGHT_RECORDS is set by the renderer (src/render/light_splat.h)"
#endif
#if CAUSTICS_LIGHT_TRACED
#define BDPT_MAX_LIGHT_VERTICES LIGHT_RECORDS
#else
#define BDPT_MAX_LIGHT_VERTICES 4
#endif
#ifndef BDPT_MAX_DEPTH
#error "BDPT_MAX_DEPTH is set by the renderer, from the integrators' facts (src/settings/integrators.cpp)"
#endif
#define BDPT_CAMERA_VERTICES (BDPT_MAX_DEPTH + 2)

struct PathVertex {
    vec3 p;
    vec3 ng;        // unit geometric normal on the side the subpath arrived from (y0: the emitting side)
    vec3 ns;        // unit shading normal on the same side (y0: ng)
    vec3 wo;        // unit direction toward the previous vertex of the same subpath (unused at y0, z0)
    vec3 beta;      // subpath throughput up to and including this vertex
    int material;
    float eta;      // n on the far side / n on the arrival side (dielectrics)
    float pdfFwd;   // area density of this vertex when sampled from its predecessor in its subpath
    float pdfRev;   // area density of this vertex when sampled from the other direction
    bool delta;     // the direction sampled here came from a delta lobe (camera vertices; see gLightDelta)
    bool dispersive;  // the subpath met a dispersive glass at or before this vertex
    float offset;     // how far rays leaving it start off its surface (ray_offset.glsl); 0 for the eye
};

PathVertex gCamera[BDPT_CAMERA_VERTICES];   // z0 (the eye) .. z_{D+1}
PathVertex gLight[BDPT_MAX_LIGHT_VERTICES];  // y0 (on an emitter) ..
#ifdef SURFACE_OPACITY
// For each light vertex on a single-sided surface its front's unit normal, else 0: the eye sees it only
// from the front (opacity.glsl), which light tracing's join to the eye checks.
vec3 gLightSingleSidedFront[BDPT_MAX_LIGHT_VERTICES];
#endif
vec3 gSpectralWeight = vec3(1.0);

void storeCameraVertex(int i, PathVertex v) { gCamera[i] = v; }
void storeLightVertex(int i, PathVertex v) { gLight[i] = v; }

// The textured Kd of each stored surface vertex (surface.glsl), which fetchMaterial alone would miss;
// kept beside PathVertex so that scenes without textures store nothing more. With metallic-roughness
// maps also the textured roughness and metallic, with specular maps the textured Ks (a normal map's
// shading normal is the vertex's ns already). Vertex colours change Kd too.
#if defined(SURFACE_TEXTURES) || defined(VERTEX_COLORS)
#define KEEPS_DIFFUSE 1
vec3 gCameraDiffuse[BDPT_CAMERA_VERTICES];
vec3 gLightDiffuse[BDPT_MAX_LIGHT_VERTICES];
#endif
#ifdef SURFACE_TEXTURES
#if HAS_MAP(ROUGHNESS_MAP_BIT)
vec2 gCameraRoughness[BDPT_CAMERA_VERTICES];  // (roughness, metallic)
vec2 gLightRoughness[BDPT_MAX_LIGHT_VERTICES];
#endif
#if HAS_MAP(SPECULAR_MAP_BIT)
vec3 gCameraSpecular[BDPT_CAMERA_VERTICES];
vec3 gLightSpecular[BDPT_MAX_LIGHT_VERTICES];
#endif
#endif

void keepDiffuse(bool camera, int i, Surface s) {
#ifdef KEEPS_DIFFUSE
    if (camera) gCameraDiffuse[i] = s.material.diffuse;
    else gLightDiffuse[i] = s.material.diffuse;
#endif
#ifdef SURFACE_TEXTURES
#if HAS_MAP(ROUGHNESS_MAP_BIT)
    if (camera) gCameraRoughness[i] = vec2(s.material.roughness, s.material.metallic);
    else gLightRoughness[i] = vec2(s.material.roughness, s.material.metallic);
#endif
#if HAS_MAP(SPECULAR_MAP_BIT)
    if (camera) gCameraSpecular[i] = s.material.specular;
    else gLightSpecular[i] = s.material.specular;
#endif
#endif
}

// The material at stored vertex i of the camera or light subpath, with its Surface's textured values.
MaterialData vertexMaterial(bool camera, int i) {
    MaterialData m = fetchMaterial(camera ? gCamera[i].material : gLight[i].material);
#ifdef KEEPS_DIFFUSE
    m.diffuse = camera ? gCameraDiffuse[i] : gLightDiffuse[i];
#endif
#ifdef SURFACE_TEXTURES
#if HAS_MAP(ROUGHNESS_MAP_BIT)
    vec2 rm = camera ? gCameraRoughness[i] : gLightRoughness[i];
    m.roughness = rm.x;
    m.metallic = rm.y;
#endif
#if HAS_MAP(SPECULAR_MAP_BIT)
    m.specular = camera ? gCameraSpecular[i] : gLightSpecular[i];
#endif
#endif
    return m;
}
// The normal a surface's path vertex keeps (PathVertex.ns): a normal map's before any bend, which
// vertexNormal makes for each join; else the shading normal.
vec3 storedNormal(Surface s) {
#ifdef NORMAL_MAPPED_SURFACES
    return s.mappedNormal;
#else
    return s.shadingNormal;
#endif
}

#if defined(NORMAL_MAPPED_SURFACES) && !CAUSTICS_LIGHT_TRACED
// Camera vertices whose sampled direction came from a delta lobe with a bent normal (surface.glsl,
// bentDelta): no light subpath goes through them, so misWeight leaves out the strategies that would.
bool gCameraBent[BDPT_CAMERA_VERTICES];
#endif

// The delta flags of the light vertices, apart from gLight: on llvmpipe (Mesa 22.3.6) `gLight[count -
// 1].delta = true` in traceLightSubpath read back false afterwards (measured with a debug copy of the
// light-tracing pass), which made the weights count impossible strategies through smooth glass.
bool gLightDelta[BDPT_MAX_LIGHT_VERTICES];

#if CAUSTICS_LIGHT_TRACED
// Whether the direction sampled at y_i came from a caustic caster's lobe (bsdf.glsl, casterLobe: a delta
// lobe, or a glossy caster's).
bool gLightCaster[BDPT_MAX_LIGHT_VERTICES];

// nee's light pass (integrators/nee.glsl) uses light tracing alone, and only for the caustic paths nee
// leaves to it, y_{s-1} joined to the camera through its smooth lobes: y1 .. y_{r-1} (r >= 2) each sampled
// a caster's lobe, and y_r .. y_{s-2}, the caustic's receiver and the surfaces its light reaches from
// there, a smooth one, at most CAUSTIC_SMOOTH_BOUNCES - 1 of them (none: the caustic seen directly; one: a
// wall lit by the caustic on the floor). Their light subpaths end where no such path goes on.
bool causticStrategy(int s) {
    if (s < 3 || !gLightCaster[1]) return false;
    int smoothSamples = 0;
    for (int i = 2; i < s - 1; ++i) {
        if (!gLightCaster[i])
            ++smoothSamples;
        else if (smoothSamples > 0)
            return false;  // a caster's lobe after the receiver
    }
    return smoothSamples < CAUSTIC_SMOOTH_BOUNCES;
}
#endif

// Whether y0 of the light subpath is a punctual light (a delta position or direction, lights.glsl): then
// no camera subpath can reach it (strategy s = 0 has density 0 for its paths, and misWeight leaves it
// out), and y0 itself is never joined to the camera (a light of no size is not seen directly).
#if PUNCTUAL_LIGHTS
bool gLightPunctual = false;
#else
const bool gLightPunctual = false;
#endif

vec3 spectralFactor(bool dispersive) { return dispersive ? gSpectralWeight : vec3(1.0); }

// The convention for delta densities in the weight ratios (pbrt-v3 16.3.4): a delta density is
// stored as 0 and counts as 1; the strategies that would need it are skipped by the delta flags.
float remap0(float pdf) { return pdf != 0.0 ? pdf : 1.0; }

// The shading normal at v for a join or a sample whose camera-side direction (away from v) is
// `cameraSide`. A normal map's normal (stored unbent in ns: surface.glsl, mappedNormal) is bent for it
// as surfaceAt bends it for a camera ray arriving along it (valid_reflection.glsl), from whichever side
// of the surface that is: so every strategy sees the BSDF the camera's paths see, f(wo, wi) with the
// normal bent for wo, whichever subpath found the vertex. BSDF sampling bends for the direction it
// arrives from (vertexPdf), as surfaceAt did.
vec3 vertexNormal(PathVertex v, vec3 cameraSide) {
#ifdef NORMAL_MAPPED_SURFACES
    if (materialMaps(v.material).w >= 0) return keepReflectionAboveFor(v.ns, v.ng, cameraSide);
#endif
    return v.ns;
}

// w in the local frame of shading normal n, as surfaceAt's frame (toLocal).
vec3 vertexLocal(vec3 n, vec3 w) {
    vec3 t, b;
    orthonormalBasis(n, t, b);
    return vec3(dot(w, t), dot(w, b), dot(w, n));
}

// A direction is usable at v if the shading and geometric normals put it on the same side.
bool agrees(PathVertex v, vec3 local, vec3 world) {
    float g = dot(world, v.ng);
    return local.z != 0.0 && g != 0.0 && (local.z > 0.0) == (g > 0.0);
}

// f(a -> b) |cos(theta_b)| at a vertex, for world directions a (toward where the transported quantity
// goes: the "wo" of bsdf.glsl) and b (the direction it arrives from). Radiance transport: bsdf.glsl as
// it is (the frame flipped when a is below the shading normal, which inverts eta). Importance transport
// (light subpaths): the adjoint BSDF f*(a, b) = f(b, a), i.e. without the 1/eta^2 radiance scaling, and
// times the shading-normal correction |a.ns| |b.ng| / (|a.ng| |b.ns|) (Veach 1997, ch. 5; pbrt-v3 16.1).
vec3 vertexBsdf(PathVertex v, MaterialData m, vec3 a, vec3 b, bool importance) {
    vec3 n = vertexNormal(v, importance ? b : a);
    vec3 la = vertexLocal(n, a), lb = vertexLocal(n, b);
    if (!agrees(v, la, a) || !agrees(v, lb, b)) return vec3(0.0);
    float eta = v.eta;
    float correction = 1.0;
    if (importance) correction = abs(la.z) * abs(dot(b, v.ng)) / (abs(dot(a, v.ng)) * abs(lb.z));
    if (la.z < 0.0) {
        la.z = -la.z;
        lb.z = -lb.z;
        eta = 1.0 / eta;
    }
    vec3 f = bsdfEval(m, la, lb, eta);
    if (importance && lb.z < 0.0) f *= eta * eta;
    return f * correction;
}

// Solid-angle density with which the BSDF's own sampling at v, arriving from direction a, picks b.
float bsdfVertexPdf(PathVertex v, MaterialData m, vec3 a, vec3 b) {
    vec3 n = vertexNormal(v, a);
    vec3 la = vertexLocal(n, a), lb = vertexLocal(n, b);
    if (!agrees(v, la, a) || !agrees(v, lb, b)) return 0.0;
    float eta = v.eta;
    if (la.z < 0.0) {
        la.z = -la.z;
        lb.z = -lb.z;
        eta = 1.0 / eta;
    }
    return bsdfPdf(m, la, lb, eta);
}

// Whether bdpt samples surface s's scattering by the mixture of sampleVertex: a normal map that is not
// a mirror's.
bool mixedSampling(Surface s) {
#ifdef NORMAL_MAPPED_SURFACES
    return materialMaps(s.materialIndex).w >= 0 && !isDeltaOnly(s.material);
#else
    return false;
#endif
}

// Solid-angle density with which bdpt's sampling at v (sampleVertex), arriving from direction a, picks
// direction b.
float vertexPdf(PathVertex v, MaterialData m, vec3 a, vec3 b) {
    float pdf = bsdfVertexPdf(v, m, a, b);
#ifdef NORMAL_MAPPED_SURFACES
    if (materialMaps(v.material).w >= 0 && !isDeltaOnly(m)) {
        float side = dot(a, v.ng) < 0.0 ? -1.0 : 1.0;
        pdf = 0.5 * pdf + 0.5 * max(0.0, side * dot(b, v.ng)) / PI;
    }
#endif
    return pdf;
}

// bdpt's sampling of the direction leaving vertex v of surface s, arrived at from world direction `from`
// (-ray.dir), with numbers u (drawBounceNumbers' bsdf), for radiance (camera subpaths) or importance
// (light subpaths). At a normal-mapped surface the BSDF bends its normal for the camera's side of each
// vertex (vertexNormal), which a light subpath learns only after sampling there: its BSDF sampling,
// bent for the side it arrived from, misses directions the camera's side can scatter into. So there half
// of the samples are the BSDF's own and half cosine-weighted about the geometric normal, which covers
// every reflection (one-sample MIS over the two, Veach 1997, section 9.2.4: weight f / the mixture's
// density, vertexPdf), the same on both subpaths. A delta lobe's sample keeps its own weight, doubled
// for the half it was drawn in. Elsewhere the BSDF's sampling as it is. bs.wi is in s's frame.
bool sampleVertex(Surface s, PathVertex v, vec3 from, vec3 u, bool importance, out BsdfSample bs) {
    vec3 wo = toLocal(s, from);
    if (!mixedSampling(s)) return bsdfSample(s.material, wo, u, s.eta, bs);
    if (u.z < 0.5) {
        if (!bsdfSample(s.material, wo, vec3(u.xy, 2.0 * u.z), s.eta, bs)) return false;
        if (bs.delta) {
            bs.weight *= 2.0;
            return true;
        }
    } else {
        float side = dot(from, v.ng) < 0.0 ? -1.0 : 1.0;
        bs = BsdfSample(toLocal(s, toWorld(sampleCosineLocal(u.xy), side * v.ng)), vec3(0.0), 0.0, false);
    }
    vec3 dir = toWorld(s, bs.wi);
    MaterialData m = s.material;
    bs.pdf = vertexPdf(v, m, from, dir);
    if (!(bs.pdf > 0.0)) return false;
    bs.weight = vertexBsdf(v, m, from, dir, importance) / bs.pdf;
    return bs.weight != vec3(0.0);
}

// Solid angle to area density at `to`: p_A = p_omega |cos(theta_to)| / r^2 (d omega = cos dA / r^2),
// with the geometric normal, so that the area measure is the true one for every strategy.
float toArea(float pdfSolidAngle, vec3 from, PathVertex to) {
    vec3 d = to.p - from;
    float d2 = dot(d, d);
    if (d2 == 0.0) return 0.0;
    return pdfSolidAngle * abs(dot(to.ng, d)) / (d2 * sqrt(d2));
}

// Visibility V(a <-> b) of the two vertices, each end nudged off its surface toward the other.
bool unoccluded(PathVertex a, PathVertex b) { return !segmentOccluded(a.p, a.ng, a.offset, b.p, b.ng, b.offset); }

// The power-heuristic weight (beta = 2) of strategy (s, t) for the path it sampled: w_s =
// p_s^2 / sum_i p_i^2 = 1 / sum_i (p_i / p_s)^2 over the strategies i in use (Veach 1997, section 10.2),
// the ratios built one vertex at a time: moving the join by one vertex multiplies p by pdfRev / pdfFwd
// of the vertex that changes subpath (pbrt-v3 16.3.4).
// The densities at the joined vertices and their neighbours depend on the join, so they are passed in:
// zRevLast, zRevPrev for z_{t-1}, z_{t-2}; yRevLast, yRevPrev for y_{s-1}, y_{s-2}; yFwdFresh is the
// area density of the emitter point of an s = 1 join (sampled afresh, not taken from gLight).
// deltaLight: the path's light vertex y0 is a punctual light, which strategy s = 0 cannot sample (pbrt-v3
// 16.3, "Multiple Importance Sampling": Vertex::IsDeltaLight in MISWeight; pbrt-v4's BDPTIntegrator the
// same). Its delta position or direction is common to every other strategy (each samples y0 by picking
// the light), so it cancels from their ratios: y1's densities are the ones that differ, a direction
// density from a point or spot light converted to area at y1, or from a directional light the disk's
// area density projected onto y1.
float misWeight(int s, int t, float zRevLast, float zRevPrev, float yRevLast, float yRevPrev, float yFwdFresh,
                bool deltaLight) {
#if CAUSTICS_LIGHT_TRACED
    return t == 1 && causticStrategy(s) ? 1.0 : 0.0;  // the paths no other estimator sums
#endif
    float sum = 0.0;
    // Fewer camera vertices: strategy (s + t - i, i) makes z_i a light vertex; i = 1 is light tracing
    // (z_1 joined to z_0, the pinhole or a lens point, which is never delta: its direction is sampled over
    // the film; a lens point's own density is the same in every strategy and cancels).
    float r = 1.0;
    for (int i = t - 1; i >= 1; --i) {
        if (s + t - i > BDPT_MAX_LIGHT_VERTICES) break;
#if defined(NORMAL_MAPPED_SURFACES) && !CAUSTICS_LIGHT_TRACED
        if (i + 1 <= t - 1 && gCameraBent[i + 1]) break;  // the light subpath would scatter at z_{i+1}
#endif
        float rev = i == t - 1 ? zRevLast : (i == t - 2 ? zRevPrev : gCamera[i].pdfRev);
        r *= remap0(rev) / remap0(gCamera[i].pdfFwd);
        bool deltaHere = i == t - 1 ? false : gCamera[i].delta;
        if (!deltaHere && !gCamera[i - 1].delta) sum += r * r;
    }
    // Fewer light vertices: strategy (i, s + t - i) makes y_i a camera vertex (i = 0: the camera subpath
    // hits the emitter).
    r = 1.0;
    for (int i = s - 1; i >= 0; --i) {
        float rev = i == s - 1 ? yRevLast : (i == s - 2 ? yRevPrev : gLight[i].pdfRev);
        float fwd = s == 1 ? yFwdFresh : gLight[i].pdfFwd;
        r *= remap0(rev) / remap0(fwd);
        bool deltaHere = i == s - 1 ? false : gLightDelta[i];
        bool deltaBefore = i > 0 ? gLightDelta[i - 1] : deltaLight;  // i = 0: strategy s = 0
        if (!deltaHere && !deltaBefore) sum += r * r;
    }
    return 1.0 / (1.0 + sum);
}

// A dispersive glass fixes the path's wavelength (surface.glsl); its spectral weight is kept apart in
// gSpectralWeight rather than folded into beta. Returns whether this vertex is dispersive.
bool meetDispersion(inout Surface s) {
    if (s.material.cauchyB <= 0.0) return false;
    bool first = gWavelength == 0.0;
    vec3 w = vec3(1.0);
    applyDispersion(s, w);
    if (first) gSpectralWeight = w;
    return true;
}

// Traces the light subpath y0 .. y_{n-1}, n <= min(BDPT_MAX_LIGHT_VERTICES, maxDepth + 1) (strategy
// (s, t) has s + t - 2 bounces, so s <= maxDepth + 1, reached by t = 1). beta of y_i is the light
// subpath weight Le(y0 -> y1) G f ... G / p(y0 ... y_i), Veach's alpha^L_i (Veach 1997, section 10.2).
// Returns n.
int traceLightSubpath(int maxDepth) {
    int n = min(BDPT_MAX_LIGHT_VERTICES, maxDepth + 1);
    for (int i = 0; i < BDPT_MAX_LIGHT_VERTICES; ++i) gLightDelta[i] = false;
#if CAUSTICS_LIGHT_TRACED
    for (int i = 0; i < BDPT_MAX_LIGHT_VERTICES; ++i) gLightCaster[i] = false;
#endif
#if PUNCTUAL_LIGHTS
    gLightPunctual = false;
#endif
    if (n == 0 || uLightCount == 0) return 0;
    EmitterPoint e = sampleEmitterPoint();
    vec3 dir, beta;
    float pdfDir;
    Ray ray;
#if PUNCTUAL_LIGHTS
    // y1's area density from a directional light: the disk's area density times |cos| at y1 (0: y1's
    // density is pdfDir converted to area, as from any other y0).
    float diskPdf = 0.0;
    if (e.punctual >= 0) {
        // Emission from a punctual light (pbrt-v4 sections 12.2 and 12.3, SampleLe; pbrt-v3 16.3,
        // "Generating the Light Subpath"): y0 has the probability of the pick for its density (a delta
        // position: pdfPos 1), and beta of y1 is I(w) / (pmf p(w)) for a point or spot light, w drawn by
        // samplePunctualDirection; a directional light's rays start uniformly on the disk of radius r
        // facing it, one radius behind the centre of the sphere that bounds the scene, so beta is
        // E / (pmf / (pi r^2)) (its direction is a delta: pdfDir 1).
        gLightPunctual = true;
        PunctualLight l = fetchPunctualLight(e.punctual);
        vec3 origin = l.position;
        if (l.type == PUNCTUAL_DIRECTIONAL) {
            dir = l.direction;
#if CAUSTICS_LIGHT_TRACED
            // Only where the caster spheres stand in its way (caustic_casters.glsl).
            origin = sampleAlongToCasters(dir, origin - l.radius * dir, rand2(), diskPdf);
#else
            vec3 t, b;
            orthonormalBasis(dir, t, b);
            vec2 u = rand2();
            float r = l.radius * sqrt(u.x), phi = 2.0 * PI * u.y;  // uniform on the disk
            origin += l.radius * -dir + r * cos(phi) * t + r * sin(phi) * b;
            diskPdf = 1.0 / (PI * l.radius * l.radius);
#endif
            pdfDir = 1.0;
            beta = l.intensity / (e.pmf * diskPdf);
        } else {
#if CAUSTICS_LIGHT_TRACED
            dir = sampleTowardCasters(origin, rand2(), pdfDir);  // (caustic_casters.glsl)
#else
            dir = samplePunctualDirection(l, rand2());
            // (not punctualDirectionPdf, whose cone test rounding could fail at the cone's edge)
            pdfDir = l.type == PUNCTUAL_POINT ? 1.0 / (4.0 * PI) : 1.0 / (2.0 * PI * (1.0 - l.cosOuter));
#endif
            beta = punctualIntensity(l, dir) / (e.pmf * pdfDir);
        }
        storeLightVertex(0, PathVertex(origin, dir, dir, dir, l.intensity / e.pmf, 0, 1.0, e.pmf,
                                       0.0, false, false, 0.0));
        if (n == 1 || pdfDir <= 0.0 || beta == vec3(0.0)) return 1;
        ray = Ray(origin, dir);
    } else
#endif
    {
        TriangleData tri = e.tri;
        vec2 b = sampleTriangle(e.unitSquare);  // by area: bdpt's vertices carry area densities
        vec3 normal = normalize(cross(tri.e1, tri.e2));
        float pdfPosition = emitterAreaPdf(tri);
        vec3 Le = emitterRadiance(e.triangle, tri, b);
        PathVertex y0 = PathVertex(tri.v0 + b.x * tri.e1 + b.y * tri.e2, normal, normal, normal, Le / pdfPosition,
                                   tri.material, 1.0, pdfPosition, 0.0, false, false, surfaceOffset(tri));
        storeLightVertex(0, y0);
        if (n == 1) return 1;

#if CAUSTICS_LIGHT_TRACED
        // Toward the caustic casters (caustic_casters.glsl): Le cos / (p_A p_dir).
        dir = sampleTowardCasters(y0.p, rand2(), pdfDir);
        float cosEmitted = dot(normal, dir);
        if (cosEmitted <= 0.0 || !(pdfDir > 0.0)) return 1;
        beta = Le * (cosEmitted / (pdfPosition * pdfDir));
#else
        // Cosine-weighted emission: Le cos / (p_A * cos / pi) = Le pi / p_A.
        dir = toWorld(sampleCosineLocal(rand2()), normal);
        pdfDir = dot(normal, dir) / PI;
        if (pdfDir <= 0.0) return 1;
        beta = Le * PI / pdfPosition;
#endif
        ray = Ray(offsetToward(y0.p, normal, y0.offset, dir), dir);
    }
    bool dispersive = false;
    int count = 1;
#if CAUSTICS_LIGHT_TRACED
    int smoothSamples = 0;  // smooth lobes sampled, from the caustic's receiver on (causticStrategy)
#endif
    while (count < n) {
        Hit hit;
        if (!traceClosest(ray, hit)) break;
        Surface s = surfaceAt(ray, hit);
        dispersive = meetDispersion(s) || dispersive;
        absorbInside(s, hit.t, beta);
        PathVertex y = PathVertex(s.position, s.geometricNormal, storedNormal(s), -ray.dir, beta,
                                  s.materialIndex, s.eta, 0.0, 0.0, false, dispersive, s.offset);
        y.pdfFwd = toArea(pdfDir, gLight[count - 1].p, y);
#if PUNCTUAL_LIGHTS
        if (count == 1 && diskPdf > 0.0) y.pdfFwd = diskPdf * abs(dot(ray.dir, y.ng));
#endif
        storeLightVertex(count, y);
        keepDiffuse(false, count, s);
#ifdef SURFACE_OPACITY
        bool singleSided = (int(fetchTriangle(hit.triangle).flags) & TRIANGLE_SINGLE_SIDED_FLAG) != 0;
        gLightSingleSidedFront[count] = singleSided ? (s.frontFace ? s.geometricNormal : -s.geometricNormal) : vec3(0.0);
#endif
        ++count;
        if (count == n) break;
#if CAUSTICS_LIGHT_TRACED
        if (smoothSamples == CAUSTIC_SMOOTH_BOUNCES - 1) break;  // no caustic path goes on from here
#endif

        vec3 wo = toLocal(s, -ray.dir);
        if (wo.z <= 0.0) break;  // -ray.dir disagrees with the shading normal: f = 0
        BsdfSample bs;
        // (The light stream's pairs are the pixel's own at every depth: rng.glsl's rand2Coherent.)
        if (!sampleVertex(s, y, -ray.dir, drawBounceNumbers(count - 1).bsdf, true, bs)) break;
        bool mixed = mixedSampling(s) && !bs.delta;  // bs.weight is the adjoint's already
#if CAUSTICS_LIGHT_TRACED
        // Smooth lobes only from the caustic's receiver on, after at least one caster's lobe; casters'
        // lobes only before it.
        bool caster = casterLobe(bs, s.material);
        gLightCaster[count - 1] = caster;
        if (!caster) {
            if (count == 2) break;  // y1 itself: no caustic
            ++smoothSamples;
        } else if (smoothSamples > 0) {
            break;
        }
#endif
        vec3 next = toWorld(s, bs.wi);
        if (!mixed && !sameSide(s, bs.wi, next)) break;
        // Adjoint BSDF (see vertexBsdf): undo the radiance scaling and correct for the shading normal.
        float cosInG = abs(dot(ray.dir, s.geometricNormal));
        if (cosInG == 0.0 || bs.wi.z == 0.0) break;
        float correction = wo.z * abs(dot(next, s.geometricNormal)) / (cosInG * abs(bs.wi.z));
        beta *= mixed ? bs.weight : bs.weight * (bs.wi.z < 0.0 ? s.eta * s.eta : 1.0) * correction;
#ifdef NORMAL_MAPPED_SURFACES
        if (bs.delta && bentDelta(s, -ray.dir, next)) break;  // (surface.glsl)
#endif
        if (bs.delta) {
            gLightDelta[count - 1] = true;
            gLight[count - 2].pdfRev = 0.0;
            pdfDir = 0.0;
        } else {
            gLight[count - 2].pdfRev = toArea(vertexPdf(y, s.material, next, -ray.dir), y.p, gLight[count - 2]);
            pdfDir = bs.pdf;
        }
        if (beta == vec3(0.0)) break;
        ray = spawnRay(s, next);
    }
    return count;
}

// The light subpath of sample `sampleIndex` of pixel `pixel`, from a random stream of its own (a function
// of the seed, the pixel and the sample index alone), so that the camera pass and the light-tracing pass
// trace the same subpath and partial renders of disjoint sample ranges use disjoint light subpaths. The
// caller's stream continues where it was.
int traceLightSubpathFor(uvec2 pixel, uint sampleIndex, int maxDepth) {
    uvec4 callerKey = rngKey;
    rngInitSecondStream(uSeed, pixel, sampleIndex);
    int n = traceLightSubpath(maxDepth);
    rngKey = callerKey;
    return n;
}
