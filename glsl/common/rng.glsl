// Random numbers. Number i of the stream of sample k at pixel p is a pure function of (seed, p, k, i),
// so a render is repeatable bit for bit and any range of samples can be rendered on its own.
//
// Counter-based: each number hashes the whole key (pixel, sample, seed, counter) with pcg4d, a bijection
// of four 32-bit words (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)). Distinct
// keys give distinct hashes, so no two streams ever share a number however many samples a render takes.
// (A generator whose streams are windows of one 32-bit sequence repeats numbers once the windows of all
// pixels and samples add up to 2^32, which a 512x512 render reaches at a few hundred samples per pixel.)
// The key packs the pixel as x | y << 16: textures are at most 16384 wide, so both fit in 16 bits.

// SAMPLER (set by the renderer, src/settings/render_settings.h): 0 independent numbers, 1 Owen-scrambled Sobol.
#ifndef SAMPLER
#error "SAMPLER is set by the renderer (src/render/renderer.cpp) or the probe that includes this"
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

void samplerInit(uint seed, uvec2 pixel, uint sampleIndex);  // per sampler, below: its per-sample state

void rngInit(uint seed, uvec2 pixel, uint sampleIndex) {
    gRngPixel = pixel;
    gRngSample = sampleIndex;
    rngKey = uvec4(pixel.x | (pixel.y << 16u), sampleIndex, seed, 0u);
    samplerInit(seed, pixel, sampleIndex);
}

// A second stream of the same sample, disjoint from the first (bdpt's light subpath): its counter
// starts half-way, far beyond the few hundred numbers a path draws.
const uint kSecondStream = 0x80000000u;

void rngInitSecondStream(uint seed, uvec2 pixel, uint sampleIndex) {
    rngInit(seed, pixel, sampleIndex);
    rngKey.w = kSecondStream;
}

// Pairs taken out of the order of the calls, by number (randAt): the lens point of a thin-lens camera
// has a pair of its own (in each stream), so that a pinhole, which draws none, and a lens that does both
// leave every other dimension where it was: with aperture 0 the image is bit for bit the pinhole's.
const uint kLensPair = 0x40000000u;  // far beyond the few hundred pairs a path draws, below kSecondStream

vec2 rand2();
vec2 rand2Coherent();  // the next pair, shared by a block of pixels where the sampler allows (below)

// The 2D point of pair `pair` of the current stream (the camera's or bdpt's light stream), without moving
// the stream on.
vec2 randAt(uint pair) {
    uint counter = rngKey.w;
    rngKey.w = (counter & kSecondStream) + pair;
    vec2 u = rand2();
    rngKey.w = counter;
    return u;
}

#if SAMPLER == 1
// ---- Owen-scrambled Sobol points, their error spread as blue noise (the default, `--sampler sobol`) ----
// Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4). Every call of rand2() takes the next
// 2D "dimension pair" d (counter rngKey.w) and returns point k (the sample index) of the first two
// Sobol dimensions, its index shuffled and its digits Owen-scrambled with hashes of (seed, d): the
// samples of one pixel in one pair are a (0, 2)-sequence, so every power-of-two prefix puts one point in
// each elementary interval (a pixel's jitter, a light's point, a BSDF direction: all stratified), and
// pairs are independent of each other (Burley's padding by independent shuffles), except pairs 0 and 1,
// the pixel jitter and the first hit's first pair, which are one 4D Sobol point (kJointPairs, below; pair 1
// then a (t, 2)-sequence with t <= 2). rand() is the first coordinate of a pair of its own.
//
// Blue noise over the screen (after Ahmed & Wonka 2020, "Screen-space blue-noise diffusion of Monte
// Carlo sampling error via hierarchical ordering of pixels", ACM TOG 39(6)): the scramble is the same
// for every pixel, and each pixel XORs the point's binary digits with a shift of its own (a digital
// shift: a (0, 2)-sequence stays one, and a scrambled point XOR a fixed shift is as uniform as the
// scrambled point, so each pixel's estimate is exactly as good as before). The shift is a linear
// function of a shuffled Z-order (Morton) index z of the pixel in its 64x64 tile, in which an aligned
// 2^j x 2^j block of pixels holds the 4^j values of z's low 2j bits. Digit q of the shift (from the
// top) is the XOR of z's bits i with i a bitwise subset of q: binomial coefficients C(q, i) mod 2
// (Lucas). Every run of n consecutive rows of that matrix is invertible on z's low n bits (the integer
// matrix C(L + a, i) factors into two unitriangular ones), so at 2^L samples per pixel, when each
// pixel's points fill every interval of 2^-L, the block's pixels still differ in the next digits, and
// the block's points together fill the intervals of 2^-(L+2j): neighbours sample different parts of
// the light, of the lobe, of the pixel, and their errors cancel, at every sample count. (pbrt-v4's
// ZSobol, index = Morton << log2(spp) | k, needs the sample count in advance.) The second coordinate
// takes z through the second Sobol dimension first, so that at one sample per pixel the block's points
// are a (0, 2j, 2)-net. The Z-order is shuffled in base 4 once per pixel (a random permutation of each
// node's four children, chosen per node: Ahmed & Wonka's isotropy) and by a binary Owen scramble per
// pair, so that pairs do not share one arrangement.
// Sample k of pixel p depends only on (seed, p, k): any range of samples renders on its own.
// Dimension layout (the order of the calls): pair 0 the pixel jitter; then per bounce, nee: the choice
// between the environment and the emitters (only in scenes with both), the emitter and the point on it
// (one pair, sampleEmitterPoint; a second one for an emitter of under 2^-12 of the power), then
// drawBounceNumbers' two pairs, the BSDF direction and (lobe choice, roulette), the latter coherent over
// 8x8 pixels from the roulette's first bounce on (rand2Coherent); bsdf and naive: drawBounceNumbers'
// two pairs; a dispersive glass draws the path's wavelength where the path first
// meets one. bdpt's light subpath starts at pair 2^31 (its second stream, scrambled per pixel: see
// rand2). Out of that order (randAt, below): the lens of a thin-lens camera, pair 2^30 of the camera
// stream, and in the light stream pairs 2^31 + 2^30 + 2s for light tracing's lens point toward light
// vertex s (camera.glsl).

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

// Owen scrambling of the binary digits of x read from the top (Burley 2020, nested_uniform_scramble),
// each digit flipped depending on the digits above it, is reverse(LK(reverse(x))): below, values and
// indices are kept reversed where that saves a reversal.

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

// A 32-bit hash of one word (Jarzynski & Olano 2020, "pcg").
uint hashWord(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// A random permutation of a node's four children (2-bit digits d), uniform over all 24, from hash h.
// Every permutation of four things is an affine map of GF(2)^2, d -> A d + b: the 6 invertible 2x2
// matrices A (GL(2, 2), which permutes the three nonzero digits as S3 does) times the 4 shifts b. A is
// given by the images (a1, a2) of digits 1 and 2, a pair of distinct nonzero digits, packed 4 bits each.
const uint kInvertibleMatrices = 0xbe7d69u;  // (a1 | a2 << 2): (1,2) (2,1) (1,3) (3,1) (2,3) (3,2)

uint permuteChild(uint d, uint h) {
    uint a = (kInvertibleMatrices >> (4u * (((h >> 16u) * 6u) >> 16u))) & 15u;
    return ((d & 1u) * (a & 3u)) ^ ((d >> 1u) * (a >> 2u)) ^ (h & 3u);
}

const uint kTileLevels = 6u;  // the Z-order covers 64x64 tiles: 12 digits of the shifts

// The pixel's Z-order index in its tile (x's bits in the even places), each base-4 digit permuted by
// a permutation hashed from the digits above it, the tile and the seed.
uint shuffledZOrder(uvec2 pixel, uint seed) {
    uvec2 local = pixel & ((1u << kTileLevels) - 1u);
    uint z = 0u;
    for (uint bit = 0u; bit < kTileLevels; ++bit)
        z |= (((local.x >> bit) & 1u) << (2u * bit)) | (((local.y >> bit) & 1u) << (2u * bit + 1u));
    uvec2 tile = pixel >> kTileLevels;
    uint tileSeed = hashWord(seed ^ hashWord(tile.x | (tile.y << 16u)));
    uint shuffled = 0u;
    for (uint level = 0u; level < kTileLevels; ++level) {
        uint shift = 2u * (kTileLevels - 1u - level);  // the digit's place, from the top
        uint node = (z >> (shift + 2u)) | (1u << (2u * level));  // which node: the digits above, tagged
        shuffled |= permuteChild((z >> shift) & 3u, hashWord(tileSeed ^ node)) << shift;
    }
    return shuffled;
}

uint gZOrderReversed;  // the pixel's shuffled Z-order index, its bits reversed
uint gSampleReversed;  // the sample index, its bits reversed
uvec3 gZOrderOf = uvec3(0xffffffffu);  // the (pixel, seed) gZOrderReversed belongs to

// Coherent pairs (rand2Coherent): the scramble is one per 8x8 block of pixels, hashed from the block, and
// no pixel's shift applies, so the block's pixels take the same point. The block key never equals the
// blue-noise pairs' constant (0x5eed50b1u): x and y of a block are below 2^11.
const uint kCoherentBlockLevels = 3u;
uint gCoherentBlockKey;

// Point k of Sobol dimensions 2 and 3, bits reversed (bit q the digit of 2^-(q+1)). Their primitive
// polynomials x^2 + x + 1 and x^3 + x + 1 and initial direction numbers (1, 3) and (1, 3, 1) are Joe &
// Kuo's (2008, "Constructing Sobol sequences with better two-dimensional projections", SIAM J. Sci.
// Comput. 30(5), table new-joe-kuo-6.21201); direction number v_i (the column of index bit i - 1) follows
// Sobol's recurrence for the polynomial (as in Bratley & Fox 1988, ACM TOMS 14(1), Algorithm 659):
// v_i = v_{i-2} ^ (v_{i-2} >> 2) ^ v_{i-1} and v_i = v_{i-3} ^ (v_{i-3} >> 3) ^ v_{i-2}. Each is made as the loop reaches its bit, so a sample costs a loop over the
// bits of k (ten at 1024 spp) and reads no table, once per sample (samplerInit).
uvec2 sobolDimensionsTwoAndThreeReversed(uint k) {
    // Kept reversed from the start (reverse(v >> s) = reverse(v) << s): v_1, v_2 = 2^31, 3 x 2^30 and
    // v_3 = 2^29 reversed are 1, 3 and 4.
    uvec2 point = uvec2(0u);
    uint x0 = 1u, x1 = 3u;          // v_i, v_{i+1} of dimension 2
    uint y0 = 1u, y1 = 3u, y2 = 4u;  // v_i .. v_{i+2} of dimension 3
    for (; k != 0u; k >>= 1u) {
        if ((k & 1u) != 0u) point ^= uvec2(x0, y0);
        uint x = x0 ^ (x0 << 2u) ^ x1;
        uint y = y0 ^ (y0 << 3u) ^ y1;
        x0 = x1, x1 = x;
        y0 = y1, y1 = y2, y2 = y;
    }
    return point;
}

// Pairs 0 and 1 of the camera stream, the pixel jitter and the first hit's first pair (nee's point on a
// light, bsdf's direction), are one 4D Sobol point: dimensions 0 to 3 at the sample index itself, not
// shuffled per pair. Padding the two by independent shuffles stratifies each 2D pair but not their
// product, and where the light a point receives changes across the pixel (every lit surface in a
// penumbra, and slowly everywhere) the error of that interplay falls only as N^-1/2: direct light on
// the Cornell box, away from the lamp, 64x64, RMSE against a long render at 16, 64, 256 and 1024 spp,
// padded 0.00139, 0.00056, 0.00029, 0.00015, joint 0.00126, 0.00043, 0.00020, 0.00007
// (BENCHMARKS.md, "Samplers"). The price: pair 1 is a (t, 2)-sequence with t up to 2 (at 8 points,
// at most 1 beyond) where it was a (0, 2)-sequence; the 4D points have t <= 3 up to 1024 points.
// (tests/render/sobol_sampler_test.cpp compares a copy that pads all pairs, kJointPairs 0u.)
const uint kJointPairs = 2u;
uvec4 gJointPoint;  // the sample's point in Sobol dimensions 0 to 3, bits reversed

void samplerInit(uint seed, uvec2 pixel, uint sampleIndex) {
    if (gZOrderOf != uvec3(pixel, seed)) {  // once per pixel of a pass, not once per sample
        gZOrderReversed = bitfieldReverse(shuffledZOrder(pixel, seed));
        gZOrderOf = uvec3(pixel, seed);
    }
    gSampleReversed = bitfieldReverse(sampleIndex);
    // Here, not in sobolPair: llvmpipe runs both sides of a branch its lanes disagree on, and the lanes of
    // paths at different bounces would pay the loop for every pair they draw.
    gJointPoint = uvec4(sampleIndex, sobolSecondReversed(sampleIndex),
                        sobolDimensionsTwoAndThreeReversed(sampleIndex));
    uvec2 block = pixel >> kCoherentBlockLevels;
    gCoherentBlockKey = block.x | (block.y << 16u);
}

// Digit q of the result is the XOR of the bits i of z with i a subset of q (a subset, or zeta,
// transform over GF(2), the transpose of sobolSecondReversed's).
uint subsetParities(uint z) {
    z ^= (z << 1u) & 0xaaaaaaaau;
    z ^= (z << 2u) & 0xccccccccu;
    z ^= (z << 4u) & 0xf0f0f0f0u;
    z ^= (z << 8u) & 0xff00ff00u;
    return z ^ (z << 16u);
}

vec2 sobolPair(bool blockWide) {
    // The camera stream's scrambles are the same for every pixel (blue noise). bdpt's light subpaths
    // (the second stream) land anywhere on the screen, where a neighbour means nothing, and a shared
    // scramble makes all pixels' light paths of one sample one stratified set whose splats pile up
    // (Cornell, 16 spp: relative MSE 2.2x that of independent numbers); they keep scrambles of their own
    // per pixel and no shift, and are then better than independent numbers (0.73x).
    bool lightStream = rngKey.w >= kSecondStream;
    uint scrambleKey = lightStream ? rngKey.x : blockWide ? gCoherentBlockKey : 0x5eed50b1u;
    uint pair = rngKey.w;
    uvec4 h = pcg4d(uvec4(rngKey.z, pair, scrambleKey, 0x0b1ad5u));
    ++rngKey.w;
    uint i = bitfieldReverse(laineKarrasPermutation(gSampleReversed, h.x));  // shuffle the samples, per pair
    // The Sobol point, bits reversed, before the pixel's shift and the scramble (selects, not a branch: a
    // branch costs llvmpipe both sides and its masks).
    uvec2 point = pair >= kJointPairs ? uvec2(i, sobolSecondReversed(i))
                  : pair == 0u        ? gJointPoint.xy
                                      : gJointPoint.zw;
    // The pixel's Z-order index, Owen-scrambled per pair.
    uint z = lightStream || blockWide ? 0u
                         : bitfieldReverse(laineKarrasPermutation(gZOrderReversed, h.w)) &
                               ((1u << (2u * kTileLevels)) - 1u);
    // All values in reversed-bit form (bit q is the digit of 2^-(q+1)): the first dimension is the
    // radical inverse, reverse(i). XOR with the pixel's shift, Owen-scramble (reverse(LK(reverse(v))):
    // the shift goes first, so that every pixel's k-th point lands in a different place), reverse.
    uint x = laineKarrasPermutation(point.x ^ subsetParities(z), h.y);
    uint y = laineKarrasPermutation(point.y ^ subsetParities(sobolSecondReversed(z)), h.z);
    return vec2(uvec2(bitfieldReverse(x), bitfieldReverse(y)) >> 8u) * (1.0 / 16777216.0);
}

vec2 rand2() { return sobolPair(false); }

// A pair for a decision that ends or branches a path (Russian roulette, the lobe choice) where a blue-noise
// arrangement buys nothing visible: the pixels of an 8x8 block take the same point, so that their paths,
// which llvmpipe runs in lanes of one vector (and a GPU in one warp), end and branch together and the
// vector loops for fewer bounces. Each pixel's points are still the same randomized (0, 2)-sequence, so each
// pixel's estimate is as good; only neighbours' errors are correlated (docs/optimisation-log.md,
// "Coherent roulette").
vec2 rand2Coherent() { return sobolPair(true); }

float rand() { return rand2().x; }
#else
void samplerInit(uint seed, uvec2 pixel, uint sampleIndex) {}

// ---- independent numbers (`--sampler independent`): the plain Monte Carlo of the textbooks ----
// Uniform in [0, 1): the hash's top 24 bits, so the float is exact. A pair takes two of the four words of
// one hash (one counter), as a Sobol pair takes one dimension pair.
vec2 rand2() {
    uvec2 words = pcg4d(rngKey).xy;
    ++rngKey.w;
    return vec2(words >> 8u) * (1.0 / 16777216.0);
}

vec2 rand2Coherent() { return rand2(); }  // independent numbers stay the textbook's: no sharing

float rand() { return rand2().x; }
#endif
