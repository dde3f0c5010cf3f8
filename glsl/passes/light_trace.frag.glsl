// Light tracing, bdpt's strategies t = 1 (see integrators/bdpt.glsl): each fragment traces the light
// subpath of sample uLightSample of a launching pixel (light_launch.glsl; for bdpt the same subpath its
// camera pass joins to), joins each of its vertices y_{s-1} to the pinhole (or to a point of a thin lens)
// by a shadow ray, and writes one record per vertex: the weighted contribution and the pixel it lands on.
// The splat pass (light_splat.*.glsl) then adds the records into the light image. With
// CAUSTICS_LIGHT_TRACED it is nee's light pass instead (integrators/nee.glsl): light subpaths aimed at the
// caustic casters (common/caustic_casters.glsl), only the caustic strategies, weight 1.
#include "common/rng.glsl"
#include "common/intersect.glsl"
#include "common/opacity.glsl"
#include "common/bsdf.glsl"
#include "common/surface.glsl"
#include "common/camera.glsl"

#include "common/render_uniforms.glsl"
#include "passes/light_launch.glsl"
uniform float uLaunchWeight;  // region pixels / launching pixels (src/render/light_splat.cpp)

#include "integrators/bdpt_subpaths.glsl"

// Record s - 1: (weighted contribution of strategy (s, 1), index of the pixel it lands on; -1: none).
layout(location = 0) out vec4 outRecords[LIGHT_RECORDS];
// (rays traced, non-finite contributions dropped, 0, 0), added at the pixel of the path (the splat pass).
layout(location = LIGHT_RECORDS) out vec4 outStats;

// Strategy (s, 1): y = y_{s-1} joined to the eye z0. The unweighted contribution is
// alpha^L_s f(y_{s-2} -> y -> z0) G(y <-> z0) We(z0 -> y) (Veach 1997, eq. 10.8 with t = 1; pbrt-v3
// 16.3.2, "t = 1"), the pinhole's alpha^E_1 being 1 (a delta position sampled with density 1): with
// G = |cos theta_y| cos theta_camera / r^2 and the cosine at y inside f (vertexBsdf). At y0 on an emitter,
// "f" is the emitter's directional distribution: 1 in front, 0 behind, Le being in alpha^L_1 = Le / p_A.
// With a thin lens z0 is a point of the lens picked uniformly by area (pbrt-v4
// PerspectiveCamera::SampleWi), from a pair of the light stream of its own for each s (rng.glsl), so
// alpha^E_1 = L (the lens area) and L We is cameraImportance (camera.glsl); the contribution lands on the
// pixel whose rays through that lens point include the one toward y.
vec3 lightToCamera(int s, out vec2 pixel) {
    PathVertex y = gLight[s - 1];
    vec3 lens = uLensRadius > 0.0 ? lensPoint(randAt(kLensPair + 2u * uint(s))) : uCameraEye;
    if (!projectThroughLens(lens, y.p, pixel)) return vec3(0.0);
    vec3 d = lens - y.p;  // toward the camera
    float dist2 = dot(d, d);
    if (dist2 == 0.0) return vec3(0.0);
    d *= inversesqrt(dist2);
    vec3 f;
    float yRevPrev = 0.0;
    MaterialData m = vertexMaterial(false, s - 1);
#ifdef SURFACE_OPACITY
    // The eye does not see a single-sided surface from behind (opacity.glsl).
    if (s > 1 && dot(gLightSingleSidedFront[s - 1], d) < 0.0) return vec3(0.0);
#endif
    if (s == 1) {
        if (gLightPunctual) return vec3(0.0);  // a light of no size is not seen (bdpt_subpaths.glsl)
        float cosLight = dot(y.ng, d);
        if (cosLight <= 0.0) return vec3(0.0);  // one-sided emitter seen from behind
        f = vec3(cosLight);
    } else {
        if (isDeltaOnly(m)) return vec3(0.0);
#if CAUSTICS_LIGHT_TRACED
        // nee's camera pass sums the paths whose first vertex is a glossy caster (integrators/nee.glsl).
        if (isGlossyCaster(m)) return vec3(0.0);
#endif
        f = vertexBsdf(y, m, y.wo, d, true);
        if (f == vec3(0.0)) return vec3(0.0);
        yRevPrev = toArea(vertexPdf(y, m, d, y.wo), y.p, gLight[s - 2]);
    }
    // The density with which the camera would have sampled y (through its pixel, from this lens point),
    // for the weights.
    float yRevLast = toArea(cameraDirectionPdf(-d), lens, y);
    float w = misWeight(s, 1, 0.0, 0.0, yRevLast, yRevPrev, s == 1 ? y.pdfFwd : 0.0, gLightPunctual);
    PathVertex eye = PathVertex(lens, uCameraForward, uCameraForward, uCameraForward, vec3(1.0), 0, 1.0,
                                1.0, 0.0, false, false, 0.0);
#ifdef SURFACE_OPACITY
    gTowardTheEye = true;  // traced from y toward the eye (opacity.glsl)
#endif
    bool visible = unoccluded(y, eye);
#ifdef SURFACE_OPACITY
    gTowardTheEye = false;
#endif
    if (!visible) return vec3(0.0);
    float cosCamera = dot(-d, uCameraForward);
    return y.beta * f * (cameraImportance(-d) * cosCamera / dist2) * w * spectralFactor(y.dispersive);
}

void main() {
    ivec2 pixel;  // the pixel whose light path this fragment traces (its records are at its slot)
    if (!launchPixel(int(gl_FragCoord.x), int(gl_FragCoord.y), pixel)) {
        for (int s = 0; s < LIGHT_RECORDS; ++s) outRecords[s] = vec4(0.0, 0.0, 0.0, -1.0);
        outStats = vec4(0.0);
        return;
    }
    gRayCount = 0.0;
    gWavelength = 0.0;
    gSpectralWeight = vec3(1.0);
    int n = traceLightSubpathFor(uvec2(pixel), uLightSample, min(uMaxDepth, BDPT_MAX_DEPTH));
    rngInitSecondStream(uSeed, uvec2(pixel), uLightSample);  // for the lens points (randAt)
    float dropped = 0.0;
    for (int s = 1; s <= LIGHT_RECORDS; ++s) {  // s > BDPT_MAX_LIGHT_VERTICES: n is smaller
        vec4 record = vec4(0.0, 0.0, 0.0, -1.0);
#if CAUSTICS_LIGHT_TRACED
        if (s <= n && causticStrategy(s)) {  // nee's light pass: the others weigh 0 (misWeight)
#else
        if (s <= n) {
#endif
            vec2 target;
            vec3 c = lightToCamera(s, target);
            // A NaN or Inf would poison a pixel of the light image forever: count it and drop it.
            if (any(isnan(c)) || any(isinf(c))) {
                dropped += 1.0;
            } else if (c != vec3(0.0)) {
                ivec2 t = ivec2(target);
                record = vec4(c * uLaunchWeight, float(t.y * int(uResolution.x) + t.x));
            }
        }
        outRecords[s - 1] = record;
    }
    outStats = vec4(gRayCount, dropped, 0.0, 0.0);
}
