// Marks in the stencil buffer the pixels the real-time pipeline's filter shades
// (DenoisePasses::filter): those whose history holds fewer than uSettledSamples samples. The others
// pass through unfiltered: once the history is long, the variance of its mean is small, eq. 5's
// luminance weight (edge_stopping.glsl) admits few neighbours and the filter changes little (measured
// on the Cornell orbit: reuse with and without the filter reach the same FLIP once the history is ten
// frames long). They are discarded here, so that the variance and a-trous passes never run for them;
// on llvmpipe even a pass that only copies a pixel costs about 3 ms at 256x256.
uniform sampler2D uSettled;  // the real-time history: (mean radiance, samples)
uniform float uSettledSamples;

out vec4 outColor;

void main() {
    if (texelFetch(uSettled, ivec2(gl_FragCoord.xy), 0).a >= uSettledSamples) discard;
    outColor = vec4(0.0);  // masked off: only the stencil is written
}
