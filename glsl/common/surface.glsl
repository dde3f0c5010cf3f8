// What an integrator needs to know about the point a ray hit.
#include "common/ray.glsl"
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/textures.glsl"
#include "common/bsdf.glsl"
#include "common/ray_offset.glsl"
#include "common/valid_reflection.glsl"

#ifdef SURFACE_TEXTURES
#if HAS_MAP(NORMAL_MAP_BIT)
#define NORMAL_MAPPED_SURFACES 1
#endif
#endif

struct Surface {
    vec3 position;
    float offset;          // how far rays leaving it start off the surface (ray_offset.glsl)
    vec3 geometricNormal;  // unit, on the side the ray came from
    vec3 shadingNormal;    // unit, interpolated from the vertices, on the same side
    vec3 tangent, bitangent;  // with shadingNormal, the local shading frame of bsdf.glsl
    MaterialData material;
    int materialIndex;     // where `material` came from, for code that stores vertices
    float eta;             // n_transmitted / n_incident for a dielectric, as seen from the ray's side
    bool frontFace;        // the ray hit the counter-clockwise side: the side that emits
#ifdef NORMAL_MAPPED_SURFACES
    // A normal map's normal on the ray's side before keepReflectionAbove bent it for this ray into
    // shadingNormal, which bdpt bends again for the camera's side of each join (bdpt_subpaths.glsl).
    vec3 mappedNormal;
#endif
};

int gSurfacesShaded = 0;  // surface interactions of the current path, for the cost view

#ifdef SURFACE_TEXTURES
// Every map material s.materialIndex has, at the hit: a colour map multiplies Kd (a metallic-roughness's
// base colour), one of emission Ke, one of specular Ks; the metallic-roughness map's G multiplies the
// roughness and B the metallic factor (glTF's channels); a normal map replaces the shading normal and
// frame. ns is the interpolated vertex normal before it was turned to the ray's side, wo the direction
// back along the ray.
void applyTextureMaps(inout Surface s, Hit hit, vec3 ns, vec3 wo) {
    ivec4 maps = materialMaps(s.materialIndex);  // (diffuse, metallic-roughness, emission, normal)
    vec4 uv = fetchTexcoord(hit.triangle, hit.uv);  // both uv slots
#if HAS_MAP(DIFFUSE_MAP_BIT)
    if (maps.x >= 0) s.material.diffuse *= sampleTexture(maps.x, uv);
#endif
#if HAS_MAP(ROUGHNESS_MAP_BIT)
    if (maps.y >= 0) {
        vec4 c = sampleLinearTexture(maps.y, uv);
        s.material.roughness *= c.g;
        s.material.metallic *= c.b;
    }
#endif
#if HAS_MAP(EMISSION_MAP_BIT)
    if (maps.z >= 0) s.material.emission *= sampleTexture(maps.z, uv);
#endif
#if HAS_MAP(SPECULAR_MAP_BIT) || HAS_MAP(NORMAL_MAP_BIT)
    vec4 extra = materialTexel(s.materialIndex * MATERIAL_TEXELS + MATERIAL_EXTRA_TEXEL);  // (metallic, scale, Ks map)
#endif
#if HAS_MAP(SPECULAR_MAP_BIT)
    if (extra.z >= 0.0) s.material.specular *= sampleTexture(int(extra.z), uv);
#endif
#if HAS_MAP(NORMAL_MAP_BIT)
    if (maps.w >= 0) {
        vec3 n = normalMapped(maps.w, extra.y, hit.triangle, hit.uv, uv, ns);
        // On the ray's side as the vertex normal was turned, then tilted back toward the geometric normal
        // until the view direction's mirror reflection stays above the surface (keepReflectionAbove).
        n = dot(ns, s.geometricNormal) < 0.0 ? -n : n;
        s.mappedNormal = n;
        s.shadingNormal = keepReflectionAbove(n, s.geometricNormal, wo);
        orthonormalBasis(s.shadingNormal, s.tangent, s.bitangent);
    }
#endif
}
#endif

#ifdef INSTANCE_NODES_START
// The instance a hit is in, from its node pair (pack/layout.h): tri (stored in the mesh's space) placed
// in the world by object-to-world (the pair's second node), and the matrices for the rest of the hit's
// frame (scene_data.glsl). Identity for world triangles.
void placeInInstance(inout TriangleData tri, int instance) {
    gInstanceLinear = mat3(1.0);
    gInstanceNormals = mat3(1.0);
    if (instance < 0) return;
    int toObject = instance * NODE_TEXELS, toWorld = toObject + NODE_TEXELS;
    tri.v0 = transformRows(toWorld, tri.v0, 1.0);
    tri.e1 = transformRows(toWorld, tri.e1, 0.0);
    tri.e2 = transformRows(toWorld, tri.e2, 0.0);
    gInstanceLinear = transpose(mat3(uintBitsToFloat(nodeTexel(toWorld).xyz), uintBitsToFloat(nodeTexel(toWorld + 1).xyz),
                                     uintBitsToFloat(nodeTexel(toWorld + 2).xyz)));
    gInstanceNormals = mat3(uintBitsToFloat(nodeTexel(toObject).xyz), uintBitsToFloat(nodeTexel(toObject + 1).xyz),
                            uintBitsToFloat(nodeTexel(toObject + 2).xyz));
}
#endif

Surface surfaceAt(Ray ray, Hit hit) {
    ++gSurfacesShaded;
    TriangleData tri = fetchTriangle(hit.triangle);
#ifdef INSTANCE_NODES_START
    placeInInstance(tri, hit.instance);
#endif
    Surface s;
    // From the barycentrics, not ray.origin + t dir, whose error grows with the ray's length and origin.
    s.position = tri.v0 + hit.uv.x * tri.e1 + hit.uv.y * tri.e2;
    s.offset = surfaceOffset(tri);
    vec3 n = normalize(cross(tri.e1, tri.e2));
    s.frontFace = dot(n, ray.dir) < 0.0;
    s.geometricNormal = s.frontFace ? n : -n;
    vec3 ns = fetchShadingNormal(hit.triangle, hit.uv);
#ifdef INSTANCE_NODES_START
    ns = normalize(gInstanceNormals * ns);
#endif
    s.shadingNormal = dot(ns, s.geometricNormal) < 0.0 ? -ns : ns;
    orthonormalBasis(s.shadingNormal, s.tangent, s.bitangent);
#ifdef NORMAL_MAPPED_SURFACES
    s.mappedNormal = s.shadingNormal;
#endif
    s.materialIndex = tri.material;
    s.material = fetchMaterial(s.materialIndex);
#ifdef SURFACE_TEXTURES
    // The one place a texture meets a material: every integrator and view reads the material from here.
#if SURFACE_MAPS == DIFFUSE_MAP_BIT
    s.material.diffuse = texturedDiffuse(s.materialIndex, s.material.diffuse, hit.triangle, hit.uv);
#else
    applyTextureMaps(s, hit, ns, -ray.dir);
#endif
#endif
#ifdef VERTEX_COLORS
    s.material.diffuse *= fetchVertexColor(hit.triangle, hit.uv).rgb;  // glTF: COLOR_0 times the base colour
#endif
    // Front faces face out of a closed glass object: a ray hitting one enters it.
    s.eta = s.frontFace ? s.material.ior : 1.0 / s.material.ior;
    return s;
}

// Dispersion (src/scene/spectrum.h explains the scheme). gWavelength is 0 until the path meets a
// dispersive glass; then one wavelength is drawn for the rest of the path and the RGB throughput is
// weighed by w(lambda) / p(lambda), which is 1 per channel on average.
float gWavelength = 0.0;

void applyDispersion(inout Surface s, inout vec3 beta) {
    if (s.material.cauchyB <= 0.0) return;
    if (gWavelength == 0.0) {
        gWavelength = SPECTRUM_MIN_NM + rand() * (SPECTRUM_MAX_NM - SPECTRUM_MIN_NM);
        vec3 t = (gWavelength - SPECTRUM_CENTRE_NM) / SPECTRUM_WIDTH_NM;
        beta *= SPECTRUM_NORMALISATION * exp(-0.5 * t * t) * (SPECTRUM_MAX_NM - SPECTRUM_MIN_NM);
    }
    // Cauchy's equation, with A chosen so that the index at the d line (587.6 nm) is the material's ior.
    float ior = s.material.ior + s.material.cauchyB * (1.0 / (gWavelength * gWavelength) - 1.0 / (587.6 * 587.6));
    s.eta = s.frontFace ? ior : 1.0 / ior;
}

// KHR_materials_volume: Beer-Lambert absorption inside a closed glass mesh. A ray that reaches the back
// face of a Dielectric (front faces face out of a closed glass object, as for eta above) has travelled
// `distance` inside it, so what the path carries over that segment is attenuated by exp(-sigma_a
// distance) (scene.h, Material::absorption; the light subpaths of bdpt and the light pass alike). A
// segment inside that ends on another surface (an object in the glass) is not attenuated. Only scenes
// with an absorbing glass compile it (MATERIAL_VOLUME, set by the renderer).
#ifndef MATERIAL_VOLUME
#define MATERIAL_VOLUME 0
#endif
void absorbInside(Surface s, float distance, inout vec3 beta) {
#if MATERIAL_VOLUME
    if (s.frontFace || s.material.type != MATERIAL_DIELECTRIC) return;
    vec3 sigma = materialTexel(s.materialIndex * MATERIAL_TEXELS + MATERIAL_VOLUME_TEXEL).rgb;
    beta *= exp(-sigma * distance);
#endif
}

vec3 toLocal(Surface s, vec3 v) { return vec3(dot(v, s.tangent), dot(v, s.bitangent), dot(v, s.shadingNormal)); }
vec3 toWorld(Surface s, vec3 v) { return v.x * s.tangent + v.y * s.bitangent + v.z * s.shadingNormal; }

// What the surface sends back along the ray that hit it: an emitter's Ke from its front face, or an
// unlit surface's base colour from either face (KHR_materials_unlit: not a light, only seen).
vec3 emittedRadiance(Surface s) {
#if HAS_TYPE(MATERIAL_UNLIT)
    if (s.material.type == MATERIAL_UNLIT) return s.material.diffuse;
#endif
    return s.frontFace ? s.material.emission : vec3(0.0);
}

// Shading normals can put a direction on one side of the shading frame and the other side of the true
// surface; such a direction cannot be followed (it would leak light through the surface).
bool sameSide(Surface s, vec3 local, vec3 world) { return (local.z > 0.0) == (dot(world, s.geometricNormal) > 0.0); }

#ifdef NORMAL_MAPPED_SURFACES
// Whether a delta lobe's direction wi, sampled from wo, met a normal map's normal bent for either of the
// two (keepReflectionAboveFor): the bend depends on the direction, so a path arriving from wi would not
// sample wo. Light subpaths end there (bdpt_subpaths.glsl), and the estimators that join or split paths
// by which end traced them leave such paths to the camera's side (bdpt's gCameraBent, nee's light pass).
bool bentDelta(Surface s, vec3 wo, vec3 wi) {
    if (materialMaps(s.materialIndex).w < 0) return false;
    vec3 n = s.mappedNormal, ng = s.geometricNormal;
    return keepReflectionAboveFor(n, ng, wo) != n || keepReflectionAboveFor(n, ng, wi) != n;
}
#endif

// A ray leaving the surface, nudged off it to the side it leaves on.
Ray spawnRay(Surface s, vec3 dir) { return Ray(offsetToward(s.position, s.geometricNormal, s.offset, dir), dir); }

// --clamp-indirect X (src/settings/render_settings.h): light that reached the first surface the camera sees after
// bouncing off another one (paths of two bounces or more) is summed apart, and each sample's sum is
// scaled down to a largest channel of at most X; direct light is never clamped. Biased (energy is
// lost), off by default (uClampIndirect 0): it trades rare bright fireflies through glass and glossy
// lobes for a darker image, as Cycles' "Clamp Indirect" does.
uniform float uClampIndirect;
vec3 gIndirect = vec3(0.0);

// Adds light c that reached the camera after `bounces` bounces.
void addLight(inout vec3 L, vec3 c, int bounces) {
    if (bounces >= 2) gIndirect += c;
    else L += c;
}

// The path's indirect light, clamped; restarts the sum for the next path.
vec3 takeIndirect() {
    vec3 c = gIndirect;
    gIndirect = vec3(0.0);
    float m = max(c.r, max(c.g, c.b));
    return uClampIndirect > 0.0 && m > uClampIndirect ? c * (uClampIndirect / m) : c;
}

const int kRouletteDepth = 3;  // Russian roulette from this bounce on (survivesRoulette)

// The random numbers that continue a path from a surface at `depth`, in the order of rng.glsl's dimension
// layout: the BSDF direction takes a pair, and the lobe choice and Russian roulette share the next pair,
// one coordinate each (three pairs would cost the Sobol sampler a third more per bounce, and a
// (0, 2)-sequence stratifies the two coordinates of a pair jointly as well as apart). Where the roulette
// decides, that pair is coherent (rng.glsl's rand2Coherent): neighbouring paths end together, which saves
// llvmpipe 5 % of the Cornell box's instructions for no change in the error, even averaged over blocks
// of pixels (docs/optimisation-log.md, "Coherent roulette").
struct BounceNumbers {
    vec3 bsdf;       // for bsdfSample: the direction (xy) and the lobe choice (z)
    float roulette;  // for survivesRoulette
};

BounceNumbers drawBounceNumbers(int depth) {
    vec2 direction = rand2();
    vec2 lobeAndRoulette = depth >= kRouletteDepth ? rand2Coherent() : rand2();
    return BounceNumbers(vec3(direction, lobeAndRoulette.x), lobeAndRoulette.y);
}

// Russian roulette (as in pbrt-v4 PathIntegrator::Li): after a few bounces, stop a path with probability
// 1 - max(beta etaScale) and reweight the survivors, which keeps the estimate unbiased. etaScale is the
// product of eta^2 over the path's refractions (refractionScale): it undoes the 1/eta^2 by which a
// refraction scales radiance (bsdf.glsl), which the path's leaving the glass undoes in beta too. On beta
// alone the roulette stopped more than half of the paths inside glass (1/1.5^2 = 0.44) and gave the
// survivors 2.25 times the weight: no bias, but the glass sphere of assets/cornell_spheres was noisier
// than Cycles'. Nor does it play at a delta bounce (`delta`: a mirror, smooth glass), which changes beta
// by little more than Fresnel's share: a path through a glass ball waits for its next scattering
// vertex, where the roulette weighs what the path really carries (docs/optimisation-log.md, "The
// roulette inside glass"). u: drawBounceNumbers'.
int gBounces = 0;  // bounces the current path survived, for the bounces view

// The factor by which a BSDF sample scales etaScale: eta^2 for a refraction, which alone of the lobes
// goes below the surface (bsdfSample's wo is above it), else 1.
float refractionScale(BsdfSample bs, Surface s) { return bs.wi.z < 0.0 ? s.eta * s.eta : 1.0; }

bool survivesRoulette(inout vec3 beta, float etaScale, bool delta, int depth, float u) {
    if (depth >= kRouletteDepth && !delta) {
        float keep = min(1.0, max(beta.r, max(beta.g, beta.b)) * etaScale);
        if (u >= keep) return false;
        beta /= keep;
    }
    ++gBounces;
    return true;
}
