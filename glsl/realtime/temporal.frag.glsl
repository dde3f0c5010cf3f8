// Temporal reuse for real-time rendering (src/realtime/temporal_pipeline.h), after the temporal
// accumulation of SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided Filtering", HPG, sec. 4.1
// and 4.2): each pixel of this frame finds where its first hit was in the previous frame, takes the
// history there where depth, normal and pixel class agree (bilinear over the valid taps), and blends
// this frame's samples into it. Unlike SVGF the history is the plain mean of radiance (weights by
// samples, alpha = s / (N + s)), not the filtered colour, and it is only capped while the camera moves:
// with a still camera it is the progressive mean of every sample, so the image converges to exactly
// what progressive rendering gives.
#include "common/luminance.glsl"
#include "denoise/accumulated_pixel.glsl"
#include "denoise/pixel_class.glsl"

uniform sampler2D uPrevRadiance;  // (mean radiance, samples N behind it; 0: no history)
uniform sampler2D uPrevAlbedo;    // (mean first-hit albedo, first moment of demodulated luminance)
uniform sampler2D uPrevMoments;   // (second moment, first-hit distance, disoccluded, 0)
uniform sampler2D uPrevGuide;     // (unit normal or 0, distance or pixel class): the filter's guide

// This frame's camera and the previous one's (scene/scene.h CameraFrame: right and up scaled by
// tan(fov / 2), right by the aspect ratio too).
uniform vec3 uEye, uForward, uRight, uUp;
uniform vec3 uPrevEye, uPrevForward, uPrevRight, uPrevUp;
uniform vec2 uResolution;
uniform int uUseHistory;      // 0: temporal reuse off, or no previous frame
uniform int uCameraMoved;     // 0: same camera as the previous frame: the history stays where it was
uniform float uMaxHistory;    // samples the history may keep while the camera moves
uniform float uMinNormalCos;  // taps whose normal turned further are rejected

layout(location = 0) out vec4 outRadiance;  // as uPrevRadiance, for the next frame
layout(location = 1) out vec4 outAlbedo;    // as uPrevAlbedo
layout(location = 2) out vec4 outMoments;   // as uPrevMoments
layout(location = 3) out vec4 outGuide;     // as uPrevGuide
layout(location = 4) out vec4 outFilter;    // the filter's input: (demodulated colour, variance or -1)
layout(location = 5) out vec4 outModulate;  // (albedo that finish.frag.glsl multiplies back, 0)

const float kMinAlbedo = 0.01;             // as prepare.frag.glsl
const float kMinFramesForVariance = 4.0;  // as SVGF: shorter histories get a spatial estimate

// Where the camera ray through the pixel centre goes, as camera.glsl's cameraRay.
vec3 rayDirection(vec2 pixel) {
    vec2 ndc = 2.0 * pixel / uResolution - 1.0;
    return normalize(uForward + ndc.x * uRight + ndc.y * uUp);
}

// The previous frame's pixel position (y up, continuous) of a direction seen from its eye; false
// behind it. Inverts cameraRay: d / (d . forward) = forward + x right + y up.
bool previousPixel(vec3 d, out vec2 pixel) {
    float z = dot(d, uPrevForward);
    if (z <= 1e-6 * length(d)) return false;
    vec3 onPlane = d / z;
    vec2 ndc = vec2(dot(onPlane, uPrevRight) / dot(uPrevRight, uPrevRight),
                    dot(onPlane, uPrevUp) / dot(uPrevUp, uPrevUp));
    pixel = (ndc + 1.0) * 0.5 * uResolution;
    return true;
}

float depthAt(ivec2 q) {
    vec4 albedoSum = texelFetch(uAlbedoSum, q, 0);
    return albedoSum.a > 0.0 ? texelFetch(uNormalDepth, q, 0).w / albedoSum.a : 0.0;
}

// How far the depth may differ between neighbouring pixels here: the smaller one-sided difference
// per axis (as edge_stopping.glsl's depthGradient), so that a slanted surface is not rejected.
float depthSlope(ivec2 p, float z) {
    float slope = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        float best = 1e30;
        for (int side = -1; side <= 1; side += 2) {
            ivec2 q = p + side * (axis == 0 ? ivec2(1, 0) : ivec2(0, 1));
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(uResolution)))) continue;
            float zq = depthAt(q);
            if (zq > 0.0) best = min(best, abs(zq - z));
        }
        if (best < 1e30) slope += best;
    }
    return slope;
}

struct Tap {
    bool valid;
    vec4 radiance, albedo, moments;
};

// Tap q of the previous frame, if it saw the same surface: the same class (hit, miss or emitter), a
// distance from its eye within tolerance of the point's, a normal within uMinNormalCos.
Tap previousTap(ivec2 q, AccumulatedPixel a, float expectedDistance, float tolerance) {
    Tap t;
    t.valid = false;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(uResolution)))) return t;
    t.radiance = texelFetch(uPrevRadiance, q, 0);
    if (t.radiance.a <= 0.0) return t;
    t.albedo = texelFetch(uPrevAlbedo, q, 0);
    t.moments = texelFetch(uPrevMoments, q, 0);
    vec4 guide = texelFetch(uPrevGuide, q, 0);
    bool prevMiss = t.moments.y <= 0.0, miss = a.depth <= 0.0;
    if (prevMiss != miss || (guide.w == kEmitter) != a.emitter) return t;
    if (!miss) {
        if (abs(t.moments.y - expectedDistance) > tolerance) return t;
        if (dot(guide.xyz, a.normal) < uMinNormalCos) return t;
    }
    t.valid = true;
    return t;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    AccumulatedPixel a = readAccumulatedPixel(p);
    float s = a.samples;
    bool miss = a.depth <= 0.0;
    vec3 albedo = (a.emitter || miss) ? vec3(1.0) : max(a.albedo, kMinAlbedo);
    float frameLuminance = luminance(a.mean / albedo);

    // The history this pixel continues.
    vec4 radiance = vec4(0.0), prevAlbedo = vec4(0.0), moments = vec4(0.0);
    if (uUseHistory == 1 && uCameraMoved == 0) {
        // The same view of the same (static) scene: every sample of the pixel belongs to its mean,
        // including those whose jittered ray hit the other side of an edge. A changed scene resets
        // the history (TemporalPipeline::reset).
        radiance = texelFetch(uPrevRadiance, p, 0);
        prevAlbedo = texelFetch(uPrevAlbedo, p, 0);
        moments = texelFetch(uPrevMoments, p, 0);
    } else if (uUseHistory == 1) {
        vec3 d = rayDirection(vec2(p) + 0.5);
        vec3 point = uEye + a.depth * d;
        vec3 fromPrev = miss ? d : point - uPrevEye;  // a miss: a direction, seen from any eye alike
        float expected = length(fromPrev);
        float tolerance = 0.02 * expected + 2.0 * depthSlope(p, a.depth);
        vec2 pixel;
        if (previousPixel(fromPrev, pixel)) {
            vec2 f = pixel - 0.5;
            ivec2 base = ivec2(floor(f));
            vec2 w = f - vec2(base);
            float weights = 0.0;
            for (int i = 0; i < 4; ++i) {
                ivec2 o = ivec2(i & 1, i >> 1);
                float wi = (o.x == 1 ? w.x : 1.0 - w.x) * (o.y == 1 ? w.y : 1.0 - w.y);
                if (wi <= 0.0) continue;
                Tap t = previousTap(base + o, a, expected, tolerance);
                if (!t.valid) continue;
                radiance += wi * t.radiance;
                prevAlbedo += wi * t.albedo;
                moments += wi * t.moments;
                weights += wi;
            }
            if (weights > 1e-3) {
                radiance /= weights;
                prevAlbedo /= weights;
                moments /= weights;
                radiance.a = min(radiance.a, uMaxHistory);
            } else {
                radiance = vec4(0.0);
            }
        }
    }

    float n = radiance.a;
    float alpha = s / (n + s);  // the running mean over every sample
    vec3 mean = mix(radiance.rgb, a.mean, alpha);
    vec3 meanAlbedo = mix(prevAlbedo.rgb, a.albedo, alpha);
    // Moments of the demodulated luminance of whole frames (of s samples each), for the variance.
    float m1 = mix(prevAlbedo.a, frameLuminance, alpha);
    float m2 = mix(moments.x, frameLuminance * frameLuminance, alpha);
    bool disoccluded = uUseHistory == 1 && n == 0.0;

    outRadiance = vec4(mean, n + s);
    outAlbedo = vec4(meanAlbedo, m1);
    outMoments = vec4(m2, a.depth, disoccluded ? 1.0 : 0.0, 0.0);
    outGuide = vec4(a.normal, a.emitter ? kEmitter : a.depth);

    // The filter works on the history's mean, demodulated by its mean albedo, which finish multiplies
    // back: where the filter passes a pixel through, the image is the history's mean exactly.
    vec3 modulate = (a.emitter || miss) ? vec3(1.0) : max(meanAlbedo, kMinAlbedo);
    float frames = (n + s) / s;
    // The variance of the history's mean: a frame's variance over the frames behind it. m2 - m1^2 is the
    // frames' variance about their own mean, (n - 1) / n of the true one: Bessel's correction makes
    // (m2 - m1^2) / (n - 1) unbiased, as the progressive prepare pass's (squares - n mean^2) / ((n - 1) n).
    float variance = frames >= kMinFramesForVariance ? max(m2 - m1 * m1, 0.0) / (frames - 1.0) : -1.0;
    outFilter = vec4(mean / modulate, variance);
    outModulate = vec4(modulate, 0.0);
}
