// The path-tracing pass: adds uSamplesPerPass samples per pixel to the running sums it reads from the
// previous accumulation target (ping-pong). The integrator is chosen at compile time: INTEGRATOR_FILE
// names one of glsl/integrators/*.glsl, each of which defines radiance(Ray); one that also defines
// PATH_SEGMENTS (nee) lets this pass extend its paths a segment at a time (main, below).
#include "common/rng.glsl"
#include "common/intersect.glsl"
#include "common/surface.glsl"
#include "common/camera.glsl"
#include "common/render_uniforms.glsl"

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

// Starts sample `index` of the pixel: its random numbers, and its camera ray.
Ray startSample(ivec2 pixel, uint index) {
    rngInit(uSeed, uvec2(pixel), index);
    gWavelength = 0.0;
#if DEBUG_VIEW == 0 || DEBUG_VIEW == VIEW_BOUNCES || DEBUG_VIEW == VIEW_COST
    // Box filter: a uniformly jittered position inside the pixel (and with a lens, a point on it).
    return primaryRay(vec2(pixel) + rand2());
#else
    Ray ray = cameraRay(vec2(pixel) + 0.5);
    gCameraRayOrigin = ray.origin;
    return ray;
#endif
}

// The pass's sums, read from the previous accumulation target and written to the next.
vec4 sum, squares, counters, normalDepth, albedo;

// Adds sample c, traced from camera ray `ray`, to the sums.
void addSample(vec3 c, Ray ray) {
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

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    sum = texelFetch(uPreviousSum, pixel, 0);
    squares = texelFetch(uPreviousSquares, pixel, 0);
    counters = texelFetch(uPreviousCounters, pixel, 0);
    gRayCount = counters.x;
    normalDepth = texelFetch(uPreviousNormalDepth, pixel, 0);
    albedo = texelFetch(uPreviousAlbedo, pixel, 0);
    // A pixel's next sample index is the number it already has, so tiles and passes of any size give
    // the same image.
    uint firstSample = uSampleOffset + uint(sum.a);
#if DEBUG_VIEW == 0 && defined(PATH_SEGMENTS) && !GUIDES
    // Path regeneration (Novak, Havran and Dachsbacher 2010, "Path Regeneration for Interactive Path
    // Tracing"): llvmpipe shades 8 pixels in the lanes of one vector and runs a loop until its last lane
    // is done, so a loop over each sample's bounces would leave the lanes of short paths idle until the
    // group's longest path ends. Here a pixel starts its next sample in the iteration after its path
    // ends: the loop runs for the largest of the lanes' total segments, not for the sum of each sample's
    // longest path (glass scene: 20 % fewer iterations, 7 % less time; docs/optimisation-log.md, "Path
    // regeneration in nee's pass"). Each sample is traced exactly as radiance() traces it: the same
    // image, bit for bit. Not with the guides, whose extra camera ray every iteration would trace.
    int done = 0;
    Ray ray = startSample(pixel, firstSample);
    CameraPath path = startPath(ray);
    while (done < uSamplesPerPass) {
        if (!extendPath(path)) {
            addSample(pathRadiance(path), ray);
            if (++done < uSamplesPerPass) {
                ray = startSample(pixel, firstSample + uint(done));
                path = startPath(ray);
            }
        }
    }
#else
    for (int i = 0; i < uSamplesPerPass; ++i) {
        Ray ray = startSample(pixel, firstSample + uint(i));
#if DEBUG_VIEW == 0
        addSample(radiance(ray), ray);
#else
        addSample(debugView(ray), ray);
#endif
    }
#endif
    outSum = sum;
    outSquares = squares;
    outCounters = vec4(gRayCount, counters.y, counters.z, 0.0);
    outNormalDepth = normalDepth;
    outAlbedo = albedo;
}
