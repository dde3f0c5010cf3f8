// Bidirectional path tracing with multiple importance sampling (Veach 1997, ch. 10; the ratio form of
// the weights follows the presentation of pbrt-v3, section 16.3).
//
// Each sample traces a light subpath y0 y1 ... (y0 uniformly on an emissive triangle picked by power, as
// lights.glsl picks it; the first direction cosine-weighted from the emitting front face) and a camera
// subpath z0 z1 ... (z0 the pinhole), and joins every prefix pair: strategy (s, t) uses s light and t
// camera vertices, a path of s + t vertices and s + t - 1 edges (bounces = s + t - 2, so --max-depth D
// allows s + t <= D + 2, exactly the paths nee and bsdf sum).
//
// Strategies included:
//   s = 0, t >= 2  the camera subpath hits the front face of an emitter (or escapes to the environment)
//   s = 1, t >= 2  next-event style: z_{t-1} joined to a point sampled afresh on an emitter
//   s >= 2, t >= 2 z_{t-1} joined to y_{s-1} by one shadow ray
// Strategies omitted:
//   t = 1 (light tracing: y_{s-1} joined to the pinhole) adds to another pixel and would need a splat pass;
//   t = 0 cannot happen with a pinhole camera. The weights are computed over the strategies actually used
//   (t >= 2 and s <= BDPT_MAX_LIGHT_VERTICES), so the sum stays unbiased. The cost: paths whose good
//   strategy is t = 1 are found no better than by nee. A caustic seen directly on a diffuse floor through
//   smooth glass (light -> glass -> glass -> floor -> camera) has only two joinable edges, at its two
//   ends: s = 0 (the camera subpath reaches the light through the glass, as in nee) and t = 1. So such a
//   caustic is exactly as noisy as with nee. The s >= 2 joins pay off where a diffuse or glossy vertex
//   lies between the delta ones and the camera vertex being joined, e.g. caustic light reflected once
//   more by a diffuse surface (light -> glass -> glass -> floor -> wall -> camera: s = 4 joins the wall
//   to the floor point the light subpath reached).
//
// Environment light: light subpaths start on emissive triangles only, so light arriving from the
// environment is found by s = 0 alone (a camera subpath that escapes), with weight 1, as in the bsdf
// integrator. That is unbiased but noisy for scenes lit mostly by the environment: use nee there.
//
// Fragment-shader limits (fixed arrays, no recursion):
//   BDPT_MAX_LIGHT_VERTICES  light subpath vertices stored (y0..y3 by default); strategies with more
//                            light vertices are not used, and the weights leave them out.
//   BDPT_MAX_DEPTH           --max-depth is clamped to this (camera vertices z0..z_{D+1} are stored);
//                            above it the image is that of depth BDPT_MAX_DEPTH.
// Russian roulette ends camera subpaths after 3 bounces, as in nee (the survivors are reweighted, so the
// estimate stays unbiased); light subpaths are short and have none.
//
// Shading normals: at a vertex, a direction is usable only if it lies on the same side of the shading
// normal as of the geometric normal, for both directions at the vertex and in every strategy (nee checks
// only the sampled one), and light subpaths use the adjoint BSDF: without the 1/eta^2 radiance scaling on
// refraction and with the shading-normal correction (Veach 1997, ch. 5; pbrt-v3 16.1).
//
// Dispersion: one wavelength per sample, drawn when either subpath first meets a dispersive glass;
// its spectral weight multiplies the contributions of paths that contain such a vertex.
#ifndef BDPT_MAX_LIGHT_VERTICES
#define BDPT_MAX_LIGHT_VERTICES 4
#endif
#ifndef BDPT_MAX_DEPTH
#define BDPT_MAX_DEPTH 12
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
    bool delta;     // the direction sampled here came from a delta lobe
    bool dispersive;  // the subpath met a dispersive glass at or before this vertex
};

PathVertex gCamera[BDPT_CAMERA_VERTICES];   // z0 (the eye) .. z_{D+1}
PathVertex gLight[BDPT_MAX_LIGHT_VERTICES];  // y0 (on an emitter) ..
vec3 gSpectralWeight = vec3(1.0);

void storeCameraVertex(int i, PathVertex v) { gCamera[i] = v; }
void storeLightVertex(int i, PathVertex v) { gLight[i] = v; }

// The textured Kd of each stored surface vertex (surface.glsl), which fetchMaterial alone would miss;
// kept beside PathVertex so that scenes without textures store nothing more.
#ifdef SURFACE_TEXTURES
vec3 gCameraDiffuse[BDPT_CAMERA_VERTICES];
vec3 gLightDiffuse[BDPT_MAX_LIGHT_VERTICES];
#endif

void keepDiffuse(bool camera, int i, Surface s) {
#ifdef SURFACE_TEXTURES
    if (camera) gCameraDiffuse[i] = s.material.diffuse;
    else gLightDiffuse[i] = s.material.diffuse;
#endif
}

// The material at stored vertex i of the camera or light subpath, with its Surface's Kd.
MaterialData vertexMaterial(bool camera, int i) {
    MaterialData m = fetchMaterial(camera ? gCamera[i].material : gLight[i].material);
#ifdef SURFACE_TEXTURES
    m.diffuse = camera ? gCameraDiffuse[i] : gLightDiffuse[i];
#endif
    return m;
}

vec3 spectralFactor(bool dispersive) { return dispersive ? gSpectralWeight : vec3(1.0); }

// The convention for delta densities in the weight ratios (pbrt-v3 16.3.4): a delta density is
// stored as 0 and counts as 1; the strategies that would need it are skipped by the delta flags.
float remap0(float pdf) { return pdf != 0.0 ? pdf : 1.0; }

vec3 vertexLocal(PathVertex v, vec3 w) {
    vec3 t, b;
    orthonormalBasis(v.ns, t, b);
    return vec3(dot(w, t), dot(w, b), dot(w, v.ns));
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
    vec3 la = vertexLocal(v, a), lb = vertexLocal(v, b);
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

// Solid-angle density with which BSDF sampling at v, arriving from direction a, picks direction b.
float vertexPdf(PathVertex v, MaterialData m, vec3 a, vec3 b) {
    vec3 la = vertexLocal(v, a), lb = vertexLocal(v, b);
    if (!agrees(v, la, a) || !agrees(v, lb, b)) return 0.0;
    float eta = v.eta;
    if (la.z < 0.0) {
        la.z = -la.z;
        lb.z = -lb.z;
        eta = 1.0 / eta;
    }
    return bsdfPdf(m, la, lb, eta);
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
bool unoccluded(PathVertex a, PathVertex b) {
    vec3 d = b.p - a.p;
    vec3 from = a.p + (dot(d, a.ng) >= 0.0 ? 1.0 : -1.0) * uRayOffset * a.ng;
    vec3 to = b.p + (dot(d, b.ng) <= 0.0 ? 1.0 : -1.0) * uRayOffset * b.ng;
    vec3 e = to - from;
    float len = length(e);
    if (len == 0.0) return false;
    return !occluded(Ray(from, e / len), len * (1.0 - 1e-4));
}

// The power-heuristic weight (beta = 2) of strategy (s, t) for the path it sampled: w_s =
// p_s^2 / sum_i p_i^2 = 1 / sum_i (p_i / p_s)^2 over the strategies i in use (Veach 1997, section 10.2),
// the ratios built one vertex at a time: moving the join by one vertex multiplies p by pdfRev / pdfFwd
// of the vertex that changes subpath (pbrt-v3 16.3.4).
// The densities at the joined vertices and their neighbours depend on the join, so they are passed in:
// zRevLast, zRevPrev for z_{t-1}, z_{t-2}; yRevLast, yRevPrev for y_{s-1}, y_{s-2}; yFwdFresh is the
// area density of the emitter point of an s = 1 join (sampled afresh, not taken from gLight).
float misWeight(int s, int t, float zRevLast, float zRevPrev, float yRevLast, float yRevPrev, float yFwdFresh) {
    float sum = 0.0;
    // Fewer camera vertices: strategy (s + t - i, i) makes z_i a light vertex. i >= 2 (no t = 1).
    float r = 1.0;
    for (int i = t - 1; i >= 2; --i) {
        if (s + t - i > BDPT_MAX_LIGHT_VERTICES) break;
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
        bool deltaHere = i == s - 1 ? false : gLight[i].delta;
        bool deltaBefore = i > 0 && gLight[i - 1].delta;  // area emitters are never delta
        if (!deltaHere && !deltaBefore) sum += r * r;
    }
    return 1.0 / (1.0 + sum);
}

// Traces the light subpath y0 .. y_{n-1}, n <= min(BDPT_MAX_LIGHT_VERTICES, maxDepth) (a light vertex
// y_{s-1} is used only with t >= 2, so s <= maxDepth). beta of y_i is the light subpath weight
// Le(y0 -> y1) G f ... G / p(y0 ... y_i), Veach's alpha^L_i (Veach 1997, section 10.2). Returns n.
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

int traceLightSubpath(int maxDepth) {
    int n = min(BDPT_MAX_LIGHT_VERTICES, maxDepth);
    if (n == 0 || uLightCount == 0) return 0;
    vec4 light = texelFetch(uLights, pickLight(rand()));
    TriangleData tri = fetchTriangle(int(light.x));
    vec2 b = sampleTriangle(rand2());
    vec3 normal = normalize(cross(tri.e1, tri.e2));
    float pdfPosition = light.z / light.w;  // pmf / area
    vec3 Le = materialEmission(tri.material);
    PathVertex y0 = PathVertex(tri.v0 + b.x * tri.e1 + b.y * tri.e2, normal, normal, normal, Le / pdfPosition,
                               tri.material, 1.0, pdfPosition, 0.0, false, false);
    storeLightVertex(0, y0);
    if (n == 1) return 1;

    // Cosine-weighted emission: Le cos / (p_A * cos / pi) = Le pi / p_A.
    vec3 dir = toWorld(sampleCosineLocal(rand2()), normal);
    float pdfDir = dot(normal, dir) / PI;
    if (pdfDir <= 0.0) return 1;
    vec3 beta = Le * PI / pdfPosition;
    Ray ray = Ray(y0.p + uRayOffset * normal, dir);
    bool dispersive = false;
    int count = 1;
    while (count < n) {
        Hit hit;
        if (!traceClosest(ray, hit)) break;
        Surface s = surfaceAt(ray, hit);
        dispersive = meetDispersion(s) || dispersive;
        PathVertex y = PathVertex(s.position, s.geometricNormal, s.shadingNormal, -ray.dir, beta,
                                  s.materialIndex, s.eta, 0.0, 0.0, false, dispersive);
        y.pdfFwd = toArea(pdfDir, gLight[count - 1].p, y);
        storeLightVertex(count, y);
        keepDiffuse(false, count, s);
        ++count;
        if (count == n) break;

        vec3 wo = toLocal(s, -ray.dir);
        if (wo.z <= 0.0) break;  // -ray.dir disagrees with the shading normal: f = 0
        BsdfSample bs;
        if (!bsdfSample(s.material, wo, vec3(rand2(), rand()), s.eta, bs)) break;
        vec3 next = toWorld(s, bs.wi);
        if (!sameSide(s, bs.wi, next)) break;
        // Adjoint BSDF (see vertexBsdf): undo the radiance scaling and correct for the shading normal.
        float cosInG = abs(dot(ray.dir, s.geometricNormal));
        if (cosInG == 0.0 || bs.wi.z == 0.0) break;
        float correction = wo.z * abs(dot(next, s.geometricNormal)) / (cosInG * abs(bs.wi.z));
        beta *= bs.weight * (bs.wi.z < 0.0 ? s.eta * s.eta : 1.0) * correction;
        if (bs.delta) {
            gLight[count - 1].delta = true;
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

// Strategy s = 1: z_{t-1} joined to a point sampled afresh on an emitter (by power, then uniformly on the
// triangle): the unweighted contribution beta_z f(z -> y) Le(y -> z) |cos(theta_y)| / (r^2 p_A(y)).
vec3 connectToLight(int t) {
    PathVertex c = gCamera[t - 1];
    vec4 light = texelFetch(uLights, pickLight(rand()));
    TriangleData tri = fetchTriangle(int(light.x));
    vec2 b = sampleTriangle(rand2());
    vec3 normal = normalize(cross(tri.e1, tri.e2));
    PathVertex y = PathVertex(tri.v0 + b.x * tri.e1 + b.y * tri.e2, normal, normal, normal, vec3(0.0),
                              tri.material, 1.0, light.z / light.w, 0.0, false, false);
    vec3 d = y.p - c.p;
    float dist2 = dot(d, d);
    if (dist2 == 0.0) return vec3(0.0);
    d *= inversesqrt(dist2);
    float cosLight = -dot(normal, d);
    if (cosLight <= 0.0) return vec3(0.0);  // one-sided emitter seen from behind
    MaterialData mc = vertexMaterial(true, t - 1);
    vec3 f = vertexBsdf(c, mc, c.wo, d, false);
    if (f == vec3(0.0)) return vec3(0.0);
    float zRevLast = toArea(cosLight / PI, y.p, c);
    float zRevPrev = t >= 4 ? toArea(vertexPdf(c, mc, d, c.wo), c.p, gCamera[t - 2]) : 0.0;
    float yRevLast = toArea(vertexPdf(c, mc, c.wo, d), c.p, y);
    float w = misWeight(1, t, zRevLast, zRevPrev, yRevLast, 0.0, y.pdfFwd);
    if (!unoccluded(c, y)) return vec3(0.0);
    vec3 Le = materialEmission(tri.material);
    return c.beta * f * Le * (cosLight / (dist2 * y.pdfFwd)) * w * spectralFactor(c.dispersive);
}

// Strategy s >= 2: z_{t-1} joined to y_{s-1}: the unweighted contribution
// alpha^L f(y -> z) G(y <-> z) f(z -> y) alpha^E (Veach 1997, section 10.2), the cosines inside the two f
// (see vertexBsdf), so G = V / r^2.
vec3 connectSubpaths(int s, int t) {
    PathVertex c = gCamera[t - 1], l = gLight[s - 1];
    MaterialData ml = vertexMaterial(false, s - 1);
    if (isDeltaOnly(ml)) return vec3(0.0);
    vec3 d = l.p - c.p;
    float dist2 = dot(d, d);
    if (dist2 == 0.0) return vec3(0.0);
    d *= inversesqrt(dist2);
    MaterialData mc = vertexMaterial(true, t - 1);
    vec3 fc = vertexBsdf(c, mc, c.wo, d, false);
    if (fc == vec3(0.0)) return vec3(0.0);
    vec3 fl = vertexBsdf(l, ml, l.wo, -d, true);
    if (fl == vec3(0.0)) return vec3(0.0);
    float zRevLast = toArea(vertexPdf(l, ml, l.wo, -d), l.p, c);
    float zRevPrev = t >= 4 ? toArea(vertexPdf(c, mc, d, c.wo), c.p, gCamera[t - 2]) : 0.0;
    float yRevLast = toArea(vertexPdf(c, mc, c.wo, d), c.p, l);
    float yRevPrev = toArea(vertexPdf(l, ml, -d, l.wo), l.p, gLight[s - 2]);
    float w = misWeight(s, t, zRevLast, zRevPrev, yRevLast, yRevPrev, 0.0);
    if (!unoccluded(c, l)) return vec3(0.0);
    return c.beta * fc * fl * l.beta / dist2 * w * spectralFactor(c.dispersive || l.dispersive);
}

// The camera subpath, evaluating every strategy (s, t) as its vertex z_{t-1} is found: the estimator
// F = sum over s, t of w_{s,t} C*_{s,t} (Veach 1997, section 10.2).
vec3 radiance(Ray ray) {
    int maxDepth = min(uMaxDepth, BDPT_MAX_DEPTH);
    gSpectralWeight = vec3(1.0);
    int lightVertices = traceLightSubpath(maxDepth);

    storeCameraVertex(0, PathVertex(ray.origin, ray.dir, ray.dir, ray.dir, vec3(1.0), 0, 1.0, 1.0, 0.0, false, false));
    vec3 L = vec3(0.0), beta = vec3(1.0);
    float pdfDir = 1.0;  // solid-angle density of the direction that led here (the camera's is not needed)
    bool dispersive = false;
    for (int depth = 0;; ++depth) {
        int t = depth + 2;  // this hit is z_{t-1}
        Hit hit;
        if (!traceClosest(ray, hit)) {
            // Only s = 0 finds the environment here (see the header): full weight.
            L += beta * environmentRadiance(ray.dir) * spectralFactor(dispersive);
            break;
        }
        Surface s = surfaceAt(ray, hit);
        dispersive = meetDispersion(s) || dispersive;
        PathVertex z = PathVertex(s.position, s.geometricNormal, s.shadingNormal, -ray.dir, beta, s.materialIndex,
                                  s.eta, 1.0, 0.0, false, dispersive);
        if (t >= 3) z.pdfFwd = toArea(pdfDir, gCamera[t - 2].p, z);
        storeCameraVertex(t - 1, z);
        keepDiffuse(true, t - 1, s);

        // s = 0: the camera subpath hit an emitter.
        vec3 Le = emittedRadiance(s);
        if (Le != vec3(0.0)) {
            TriangleData tri = fetchTriangle(hit.triangle);
            float area = 0.5 * length(cross(tri.e1, tri.e2));
            float zRevPrev = t >= 4 ? toArea(dot(s.geometricNormal, z.wo) / PI, z.p, gCamera[t - 2]) : 0.0;
            L += beta * Le * misWeight(0, t, tri.lightPmf / area, zRevPrev, 0.0, 0.0, 0.0) * spectralFactor(dispersive);
        }
        if (depth >= maxDepth) break;

        vec3 wo = toLocal(s, -ray.dir);
        if (wo.z <= 0.0) break;  // -ray.dir disagrees with the shading normal: f = 0 (see the header)
        if (!isDeltaOnly(s.material) && uLightCount > 0) {
            L += connectToLight(t);
            int sMax = min(lightVertices, maxDepth - depth);  // s + t <= maxDepth + 2
            for (int sl = 2; sl <= sMax; ++sl) L += connectSubpaths(sl, t);
        }

        BsdfSample bs;
        if (!bsdfSample(s.material, wo, vec3(rand2(), rand()), s.eta, bs)) break;
        vec3 dir = toWorld(s, bs.wi);
        if (!sameSide(s, bs.wi, dir)) break;
        beta *= bs.weight;
        if (bs.delta) {
            gCamera[t - 1].delta = true;
            if (t >= 3) gCamera[t - 2].pdfRev = 0.0;
            pdfDir = 0.0;
        } else {
            if (t >= 3) gCamera[t - 2].pdfRev = toArea(vertexPdf(z, s.material, dir, -ray.dir), z.p, gCamera[t - 2]);
            pdfDir = bs.pdf;
        }
        if (!survivesRoulette(beta, depth)) break;
        ray = spawnRay(s, dir);
    }
    return L;
}
