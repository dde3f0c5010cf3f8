// The real-time pipeline's last pass (src/realtime/temporal_pipeline.h): the image, or a debug view
// for the classroom (one value per pixel in every channel, which the display pass shows as a heat map).
//
// The image is the filtered history, faded towards the history's plain mean once a pixel holds more
// samples than a moving camera keeps (uMaxHistory): weight min(1, uMaxHistory / N) on the filtered
// colour. While the camera moves nothing changes; once it stops, the filter's bias falls as 1 / N,
// faster than the Monte Carlo error (1 / sqrt N), so the image converges to the progressive one.
uniform sampler2D uRadiance;  // the history: (mean radiance, samples N)
uniform sampler2D uMoments;   // (second moment, distance, disoccluded, 0)
uniform sampler2D uFilter;    // the filter's input: (demodulated colour, variance of its mean or -1)
uniform sampler2D uFiltered;  // the filtered history (radiance, 1)
uniform int uUseFiltered;     // 0: no filter
uniform float uMaxHistory;
uniform float uSamplesPerFrame;
uniform int uView;  // 0: the image, 1: history length in frames, 2: the standard deviation the filter
                    // is given (0 where it estimates it spatially), 3: disocclusion

out vec4 outResult;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 history = texelFetch(uRadiance, p, 0);
    if (uView == 0) {
        vec3 color = history.rgb;
        if (uUseFiltered == 1)
            color = mix(color, texelFetch(uFiltered, p, 0).rgb, min(1.0, uMaxHistory / max(history.a, 1e-30)));
        outResult = vec4(color, 1.0);
        return;
    }
    float v;
    if (uView == 1)
        v = history.a / uSamplesPerFrame;
    else if (uView == 2)
        v = sqrt(max(texelFetch(uFilter, p, 0).a, 0.0));
    else
        v = texelFetch(uMoments, p, 0).z;
    outResult = vec4(vec3(v), 1.0);
}
