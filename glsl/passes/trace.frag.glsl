// The path-tracing pass: adds uSamplesPerPass samples per pixel to the running sums it reads from the
// previous accumulation target (ping-pong). The integrator is chosen at compile time: INTEGRATOR_FILE
// names one of glsl/integrators/*.glsl, each of which defines radiance(Ray).
#include "common/rng.glsl"
#include "common/sampling.glsl"
#include "common/scene_data.glsl"
#include "common/textures.glsl"
#include "common/intersect.glsl"
#include "common/bsdf.glsl"
#include "common/surface.glsl"
#include "common/lights.glsl"
#include "common/camera.glsl"

uniform int uMaxDepth;
uniform uint uSeed;
uniform uint uSampleOffset;  // added to every sample index (to render one range of a larger render)
uniform int uSamplesPerPass;
uniform sampler2D uPreviousSum;
uniform sampler2D uPreviousSquares;
uniform sampler2D uPreviousCounters;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousAlbedo;

#include INTEGRATOR_FILE
#include "passes/guides.glsl"
#include "passes/debug_views.glsl"

// The attachments of src/render/render_targets.h, in order.
layout(location = 0) out vec4 outSum;      // (sum of radiance, number of samples)
layout(location = 1) out vec4 outSquares;  // (sum of squared radiance, number of non-finite samples dropped)
layout(location = 2) out vec4 outCounters; // (rays traced, first hits on an emitter, first hits, 0)
layout(location = 3) out vec4 outNormalDepth;  // guides (passes/guides.glsl): (sum of normals, sum of distances)
layout(location = 4) out vec4 outAlbedo;       // (sum of albedos, guide samples)

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(uPreviousSum, pixel, 0);
    vec4 squares = texelFetch(uPreviousSquares, pixel, 0);
    vec4 counters = texelFetch(uPreviousCounters, pixel, 0);
    gRayCount = counters.x;
    vec4 normalDepth = texelFetch(uPreviousNormalDepth, pixel, 0);
    vec4 albedo = texelFetch(uPreviousAlbedo, pixel, 0);
    // A pixel's next sample index is the number it already has, so tiles and passes of any size give
    // the same image.
    uint firstSample = uSampleOffset + uint(sum.a);
    for (int i = 0; i < uSamplesPerPass; ++i) {
        rngInit(uSeed, uvec2(pixel), firstSample + uint(i));
        gWavelength = 0.0;
#if DEBUG_VIEW == 0 || DEBUG_VIEW == VIEW_BOUNCES || DEBUG_VIEW == VIEW_COST
        // Box filter: a uniformly jittered position inside the pixel (and with a lens, a point on it).
        Ray ray = primaryRay(vec2(pixel) + rand2());
#else
        Ray ray = cameraRay(vec2(pixel) + 0.5);
        gCameraRayOrigin = ray.origin;
#endif
#if DEBUG_VIEW == 0
        vec3 c = radiance(ray);
#else
        vec3 c = debugView(ray);
#endif
#if GUIDES
        addFirstHitGuides(ray, normalDepth, albedo, counters.y, counters.z);
#endif
        // A NaN or Inf sample would poison the pixel forever: count it, and add 0 instead.
        if (any(isnan(c)) || any(isinf(c))) {
            squares.a += 1.0;
            c = vec3(0.0);
        }
        sum += vec4(c, 1.0);
        squares.rgb += c * c;
    }
    outSum = sum;
    outSquares = squares;
    outCounters = vec4(gRayCount, counters.y, counters.z, 0.0);
    outNormalDepth = normalDepth;
    outAlbedo = albedo;
}
