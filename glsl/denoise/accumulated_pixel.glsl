// One pixel of an accumulation (src/render/render_targets.h) as the denoising and real-time passes read
// it: the mean radiance and the first-hit guides (passes/guides.glsl), averaged over its samples.
uniform sampler2D uSum;          // (sum of radiance, samples)
uniform sampler2D uCounters;     // (rays, samples whose first hit was an emitter, first hits, 0)
uniform sampler2D uNormalDepth;  // (sum of first-hit normals, sum of first-hit distances)
uniform sampler2D uAlbedoSum;    // (sum of first-hit albedos, guide samples)
uniform sampler2D uSplatSum;    // bdpt's light image (render/light_splat.h): (sum of contributions, rays)
uniform float uLightPaths;       // light paths per pixel behind uSplatSum; 0: no light image

struct AccumulatedPixel {
    float samples;   // 0: not rendered yet
    vec3 cameraMean; // the camera samples' mean alone, without the light image
    vec3 mean;       // the estimate: the camera mean, plus bdpt's light image (Accumulation::mean)
    vec3 normal;     // unit mean first-hit normal; 0 where every sample missed (or no guides)
    float depth;     // mean first-hit distance; 0 where none hit
    vec3 albedo;     // mean first-hit albedo; 0 where none hit
    bool emitter;    // some sample's first hit was an emitter
    bool hasGuides;  // guides were accumulated (not after a resumed render, whose guides are not saved)
};

AccumulatedPixel readAccumulatedPixel(ivec2 p) {
    AccumulatedPixel a;
    vec4 sum = texelFetch(uSum, p, 0);
    a.samples = sum.a;
    a.cameraMean = a.samples > 0.0 ? sum.rgb / a.samples : vec3(0.0);
    a.mean = a.cameraMean;
    if (a.samples > 0.0 && uLightPaths > 0.0) a.mean += texelFetch(uSplatSum, p, 0).rgb / uLightPaths;
    vec4 normalDepth = texelFetch(uNormalDepth, p, 0), albedoSum = texelFetch(uAlbedoSum, p, 0);
    float guideSamples = albedoSum.a;
    a.hasGuides = guideSamples > 0.0;
    a.normal = vec3(0.0);
    a.depth = 0.0;
    a.albedo = vec3(0.0);
    a.emitter = false;
    if (a.hasGuides) {
        vec3 meanNormal = normalDepth.xyz / guideSamples;
        a.normal = dot(meanNormal, meanNormal) > 1e-12 ? normalize(meanNormal) : vec3(0.0);
        a.depth = normalDepth.w / guideSamples;
        a.albedo = albedoSum.rgb / guideSamples;
        a.emitter = texelFetch(uCounters, p, 0).y > 0.0;
    }
    return a;
}
