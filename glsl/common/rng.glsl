// Random numbers. Number i of the stream of sample k at pixel p is a pure function of (seed, p, k, i),
// so a render is repeatable bit for bit and any range of samples can be rendered on its own.
//
// Counter-based: each number hashes the whole key (pixel, sample, seed, counter) with pcg4d, a bijection
// of four 32-bit words (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)). Distinct
// keys give distinct hashes, so no two streams ever share a number however many samples a render takes.
// (A generator whose streams are windows of one 32-bit sequence repeats numbers once the windows of all
// pixels and samples add up to 2^32, which a 512x512 render reaches at a few hundred samples per pixel.)
// The key packs the pixel as x | y << 16: textures are at most 16384 wide, so both fit in 16 bits.

uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v ^= v >> 16u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

uvec4 rngKey;  // (pixel.x | pixel.y << 16, sample index, seed, counter)
uvec2 gRngPixel;  // the pixel and sample index of the last rngInit: the sample being traced
uint gRngSample;

void rngInit(uint seed, uvec2 pixel, uint sampleIndex) {
    gRngPixel = pixel;
    gRngSample = sampleIndex;
    rngKey = uvec4(pixel.x | (pixel.y << 16u), sampleIndex, seed, 0u);
}

// A second stream of the same sample, disjoint from the first (bdpt's light subpath): its counter
// starts half-way, far beyond the few hundred numbers a path draws.
void rngInitSecondStream(uint seed, uvec2 pixel, uint sampleIndex) {
    rngInit(seed, pixel, sampleIndex);
    rngKey.w = 0x80000000u;
}

// Uniform in [0, 1): the hash's top 24 bits, so the float is exact.
float rand() {
    uint word = pcg4d(rngKey).x;
    ++rngKey.w;
    return float(word >> 8u) * (1.0 / 16777216.0);
}

vec2 rand2() {
    float x = rand();
    return vec2(x, rand());
}
