// The first-hit guides of the denoisers (src/denoise/): what each sample's camera ray hits first,
// summed over the samples like the radiance. Traced once more rather than taken from the integrator,
// so that the integrators stay as they are; that ray is not counted in the rays/s figure.
#include "common/intersect.glsl"
#include "common/surface.glsl"

// The albedo the `albedo` view shows and the denoisers divide out.
vec3 surfaceAlbedo(Surface s) { return s.material.diffuse; }

// normalDepth: (shading normal, distance along the unit ray); albedo: (albedo, guide samples); a miss
// adds zeros and one guide sample. emitterHits counts first hits on the emitting side of an emitter,
// surfaceHits every first hit (the depth AOV averages the distances over those, src/render/aovs.h).
void addFirstHitGuides(Ray ray, inout vec4 normalDepth, inout vec4 albedo, inout float emitterHits,
                       inout float surfaceHits) {
    float rays = gRayCount;
    Hit hit;
    if (traceClosest(ray, hit)) {
        Surface s = surfaceAt(ray, hit);
        normalDepth += vec4(s.shadingNormal, hit.t);
        albedo.rgb += surfaceAlbedo(s);
        if (any(greaterThan(emittedRadiance(s), vec3(0.0)))) emitterHits += 1.0;
        surfaceHits += 1.0;
    }
    albedo.a += 1.0;
    gRayCount = rays;
}
