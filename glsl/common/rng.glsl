// Random numbers. The stream of sample k at pixel p is a pure function of (seed, p, k), so a render
// is repeatable bit for bit and any range of samples can be rendered on its own.

// PCG hash: Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint rngState;
uvec2 gRngPixel;  // the pixel and sample index of the last rngInit: the sample being traced
uint gRngSample;

void rngInit(uint seed, uvec2 pixel, uint sampleIndex) {
    gRngPixel = pixel;
    gRngSample = sampleIndex;
    rngState = pcgHash(seed ^ pcgHash(pixel.x ^ pcgHash(pixel.y ^ pcgHash(sampleIndex))));
}

// A second stream of the same sample, independent of the first (bdpt's light subpath).
void rngInitSecondStream(uint seed, uvec2 pixel, uint sampleIndex) {
    rngInit(seed, pixel, sampleIndex);
    rngState = pcgHash(rngState ^ 0x9e3779b9u);
}

// Uniform in [0, 1): the PCG-RXS-M-XS step, keeping 24 bits so the float is exact.
float rand() {
    rngState = rngState * 747796405u + 2891336453u;
    uint word = ((rngState >> ((rngState >> 28u) + 4u)) ^ rngState) * 277803737u;
    return float(((word >> 22u) ^ word) >> 8u) * (1.0 / 16777216.0);
}

vec2 rand2() { return vec2(rand(), rand()); }
