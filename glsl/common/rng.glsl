// Random numbers. Number i of the stream of sample k at pixel p is a pure function of (seed, p, k, i),
// so a render is repeatable bit for bit and any range of samples can be rendered on its own.
//
// Counter-based: each number hashes the whole key (pixel, sample, seed, counter) with pcg4d, a bijection
// of four 32-bit words (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)). Distinct
// keys give distinct hashes, so no two streams ever share a number however many samples a render takes.
// (A generator whose streams are windows of one 32-bit sequence repeats numbers once the windows of all
// pixels and samples add up to 2^32, which a 512x512 render reaches at a few hundred samples per pixel.)
// The key packs the pixel as x | y << 16: textures are at most 16384 wide, so both fit in 16 bits.

// SAMPLER (set by the renderer, src/render/settings.h): 0 independent numbers, 1 Owen-scrambled Sobol.
#ifndef SAMPLER
#define SAMPLER 0
#endif

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

#if SAMPLER == 1
// ---- Owen-scrambled Sobol points (the default sampler, `--sampler sobol`) ----
// Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4). Every call of rand2() takes the next
// 2D "dimension pair" d (counter rngKey.w) and returns point k (the sample index) of the first two
// Sobol dimensions, shuffled and Owen-scrambled with hashes of (pixel, seed, d): the samples of one pixel
// in one pair are a (0, 2)-sequence, so every power-of-two prefix puts one point in each elementary
// interval (a pixel's jitter, a light's point, a BSDF direction: all stratified), and pairs are
// independent of each other (Burley's padding by independent shuffles). rand() is the first coordinate
// of a pair of its own. Sample k of pixel p still depends only on (seed, p, k).
// Dimension layout (the order of the calls): pair 0 the pixel jitter; then per bounce, nee: light
// choice, emitter pick, point on the emitter (2D), BSDF direction (2D), BSDF lobe, roulette; bsdf and
// naive: BSDF direction, lobe, roulette; bdpt's light subpath starts at pair 2^31 (its second stream).

// Laine & Karras 2011 style permutation, with Burley's constants: flips each bit of x depending on
// the bits below it only.
uint laineKarrasPermutation(uint x, uint seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scrambling of the binary digits of x read from the top (Burley 2020, nested_uniform_scramble):
// each digit flips depending on the digits above it.
uint nestedUniformScramble(uint x, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

// The second Sobol dimension (primitive polynomial x + 1) with its bits reversed: its generator matrix
// is Pascal's triangle mod 2, so by Lucas' theorem bit j of the reversed point is the parity of the index
// bits k whose binary digits contain j's (a superset, or zeta, transform over GF(2)): five shifts in
// place of a loop over the index bits.
uint sobolSecondReversed(uint i) {
    i ^= (i >> 1u) & 0x55555555u;
    i ^= (i >> 2u) & 0x33333333u;
    i ^= (i >> 4u) & 0x0f0f0f0fu;
    i ^= (i >> 8u) & 0x00ff00ffu;
    return i ^ (i >> 16u);
}

vec2 rand2() {
    uvec3 h = pcg4d(uvec4(rngKey.x, rngKey.z, rngKey.w, 0x5eed50b1u)).xyz;
    ++rngKey.w;
    uint i = nestedUniformScramble(rngKey.y, h.x);  // shuffle the pixel's samples, per pair
    // Both dimensions are reversed-bit values: the first is the radical inverse, reverse(i). Owen
    // scrambling a value is reverse(LK(reverse(value))), so each point is reverse(LK(reversed point)).
    uint x = bitfieldReverse(laineKarrasPermutation(i, h.y));
    uint y = bitfieldReverse(laineKarrasPermutation(sobolSecondReversed(i), h.z));
    return vec2(uvec2(x, y) >> 8u) * (1.0 / 16777216.0);
}

float rand() { return rand2().x; }
#else
// ---- independent numbers (`--sampler independent`): the plain Monte Carlo of the textbooks ----
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
#endif
