// The random streams of glsl/common/rng.glsl, read back through a probe pass: no two (pixel, sample)
// streams may share numbers. A generator whose streams are windows of one 32-bit sequence fails this
// once the windows of all the streams add up to a sizeable part of 2^32 (a 512x512 render at a few
// hundred samples per pixel): two streams then run through the same numbers, shifted, and the pixels
// or samples that own them are correlated instead of independent.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

constexpr int kSize = 128;         // pixels per side
constexpr int kNumbers = 8;        // numbers read per stream
constexpr uint32_t kSamples = 16;  // streams per pixel

// One draw of the probe over a width x height viewport; returns its two attachments, rows bottom first.
std::array<std::vector<glm::vec4>, 2> drawProbe(Program& program, int width, int height) {
    GLuint textures[2], framebuffer, vertexArray;
    glGenTextures(2, textures);
    glGenFramebuffers(1, &framebuffer);
    glGenVertexArrays(1, &vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    for (int i = 0; i < 2; ++i) {
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, textures[i],
                               0);
    }
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    program.use();
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::array<std::vector<glm::vec4>, 2> out;
    for (int i = 0; i < 2; ++i) {
        out[size_t(i)].resize(size_t(width) * size_t(height));
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out[size_t(i)].data());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(2, textures);
    if (glGetError() != GL_NO_ERROR) throw Error("random-stream probe: GL error");
    return out;
}

// The probe compiled for one sampler (0 independent, 1 Sobol: glsl/common/rng.glsl), from the test
// shaders (FP_RENDER_TEST_SHADERS: to check that these tests fail on a generator with overlapping
// streams, or on a broken scramble).
Program probeProgram(int sampler) {
    return Program(testShaders(), "passes/fullscreen.vert.glsl", "tests/rng_probe.frag.glsl",
                   {{"SAMPLER", std::to_string(sampler)}});
}

// The first kNumbers numbers of every stream of sample `sample`, as the 24-bit integers rand() scales.
std::vector<uint32_t> streams(Program& program, uint32_t seed, uint32_t sample) {
    program.use();
    program.set("uMode", 0);
    program.set("uSeed", seed);
    program.set("uSample", sample);
    std::array<std::vector<glm::vec4>, 2> halves = drawProbe(program, kSize, kSize);
    std::vector<uint32_t> numbers;
    numbers.reserve(halves[0].size() * kNumbers);
    for (size_t p = 0; p < halves[0].size(); ++p)
        for (int i = 0; i < kNumbers; ++i)
            numbers.push_back(uint32_t(halves[size_t(i / 4)][p][i % 4] * 16777216.0f));  // exact: 24 bits
    return numbers;
}

// Samples 0 .. count-1 of one pixel: the 2D points of dimension pairs 0 (xy) and 1 (zw); pair 0 drawn
// by rand2Coherent when `coherentFirst`.
std::vector<glm::vec4> pixelSamples(Program& program, uint32_t seed, glm::uvec2 pixel, int count,
                                    bool coherentFirst = false) {
    const int width = 64;
    program.use();
    program.set("uMode", coherentFirst ? 2 : 1);
    program.set("uSeed", seed);
    program.set("uPixel", glm::ivec2(pixel));
    program.set("uWidth", width);
    std::vector<glm::vec4> points = drawProbe(program, width, (count + width - 1) / width)[0];
    points.resize(size_t(count));
    return points;
}

TEST(RandomStreams, NoTwoStreamsShareNumbers) {
    ensureGlContext();
    Program program = probeProgram(0);
    // Every pair of consecutive numbers, 48 bits, and where it was seen. 262144 streams of 7 pairs among
    // 2^48 values: independent streams repeat a pair by chance with probability below 1 %, and the
    // seed is fixed, so this passes or fails for good. Streams that overlap repeat many.
    std::unordered_map<uint64_t, uint32_t> seen;
    seen.reserve(size_t(kSize) * kSize * kSamples * (kNumbers - 1));
    int repeats = 0;
    for (uint32_t sample = 0; sample < kSamples; ++sample) {
        std::vector<uint32_t> numbers = streams(program, 7, sample);
        for (size_t stream = 0; stream < numbers.size() / kNumbers; ++stream)
            for (int i = 0; i + 1 < kNumbers; ++i) {
                uint64_t pair =
                    (uint64_t(numbers[stream * kNumbers + i]) << 24) | numbers[stream * kNumbers + i + 1];
                auto [it, fresh] = seen.emplace(pair, uint32_t(sample * kSize * kSize + stream));
                if (!fresh && it->second != uint32_t(sample * kSize * kSize + stream)) ++repeats;
            }
    }
    EXPECT_EQ(repeats, 0) << "consecutive numbers that two different (pixel, sample) streams share";
    // And they are uniform on [0, 1): the mean of 131072 of them is 1/2 within 5 standard errors.
    double sum = 0.0;
    std::vector<uint32_t> numbers = streams(program, 7, 0);
    for (uint32_t n : numbers) sum += double(n) / 16777216.0;
    EXPECT_NEAR(sum / double(numbers.size()), 0.5, 5.0 * 0.2887 / std::sqrt(double(numbers.size())));
}

// Whether every elementary box of `dims` coordinates of the first 2^m points, [i_d / 2^a_d, (i_d + 1) /
// 2^a_d) in coordinate d with sum a_d = m - t, holds exactly 2^t of them: a (t, m, s)-net.
bool isNet(const std::vector<std::array<float, 4>>& points, int dims, int m, int t) {
    const int q = m - t;
    std::vector<int> a(size_t(dims), 0);
    std::function<bool(int, int)> boxes = [&](int d, int left) -> bool {
        if (d == dims - 1) {
            a[size_t(d)] = left;
            std::vector<int> cells(size_t(1) << q, 0);
            for (int k = 0; k < (1 << m); ++k) {
                size_t cell = 0;
                for (int c = 0; c < dims; ++c)
                    cell = cell << a[size_t(c)] |
                           size_t(points[size_t(k)][size_t(c)] * float(1 << a[size_t(c)]));
                ++cells[cell];
            }
            for (int n : cells)
                if (n != 1 << t) return false;
            return true;
        }
        for (a[size_t(d)] = 0; a[size_t(d)] <= left; ++a[size_t(d)])
            if (!boxes(d + 1, left - a[size_t(d)])) return false;
        return true;
    };
    return boxes(0, q);
}

// Owen-scrambled Sobol points (Burley 2020; a nested scramble maps elementary boxes onto elementary
// boxes, so it keeps these properties). Pair 0, the pixel jitter, is a (0, 2)-sequence: every
// power-of-two prefix is a (0, m, 2)-net. Pairs 0 and 1 are one 4D Sobol point (rng.glsl,
// kJointPairs): every prefix is a (t, m, 4)-net with t <= 3 (Sobol dimensions 0 to 3; computed
// for m <= 10 from their generator matrices), and pair 1 alone a (t, m, 2)-net with t <= 2 and each of
// its coordinates a (0, m, 1)-net. Catches a wrong generator matrix, a scramble that
// is not nested (flipping a digit by anything but the digits above it), and pairs 0 and 1 padded by
// independent shuffles (each still stratified, their product not: no (3, m, 4)-net from m = 5 on).
void expectEveryPrefixStratified(Program& program, bool coherentFirst) {
    for (uint32_t seed : {0u, 7u})
        for (glm::uvec2 pixel : {glm::uvec2(0, 0), glm::uvec2(5, 300)}) {
            std::vector<glm::vec4> samples = pixelSamples(program, seed, pixel, 1024, coherentFirst);
            std::vector<std::array<float, 4>> pair0, pair1, pair1x, pair1y, joint;
            for (const glm::vec4& p : samples) {
                pair0.push_back({p.x, p.y, 0.0f, 0.0f});
                pair1.push_back({p.z, p.w, 0.0f, 0.0f});
                pair1x.push_back({p.z, 0.0f, 0.0f, 0.0f});
                pair1y.push_back({p.w, 0.0f, 0.0f, 0.0f});
                joint.push_back({p.x, p.y, p.z, p.w});
            }
            const std::string where = "seed " + std::to_string(seed) + ", pixel " + std::to_string(pixel.x) +
                                      "," + std::to_string(pixel.y) +
                                      (coherentFirst ? " (coherent first)" : "");
            for (int m = 0; m <= 10; ++m) {
                ASSERT_TRUE(isNet(pair0, 2, m, 0)) << where << ": pair 0, " << (1 << m) << " points";
                ASSERT_TRUE(isNet(pair1x, 1, m, 0)) << where << ": pair 1 x, " << (1 << m) << " points";
                ASSERT_TRUE(isNet(pair1y, 1, m, 0)) << where << ": pair 1 y, " << (1 << m) << " points";
                ASSERT_TRUE(isNet(pair1, 2, m, std::min(m, 2)))
                    << where << ": pair 1, " << (1 << m) << " points";
                ASSERT_TRUE(isNet(joint, 4, m, std::min(m, 3)))
                    << where << ": pairs 0 and 1 as one 4D point, " << (1 << m) << " points";
            }
        }
}

TEST(SobolSampler, EveryPowerOfTwoPrefixIsStratified) {
    ensureGlContext();
    Program program = probeProgram(1);
    expectEveryPrefixStratified(program, false);
}

// rand2Coherent (rng.glsl, for Russian roulette): the pixels of an aligned 8x8 block take one point, other
// blocks other points, and each pixel's samples are still a (0, 2)-sequence, as are the blue-noise pair's
// drawn after it. Catches a shared pair keyed by the pixel (no coherence: no saving) or by nothing (one
// point for the whole image: every pixel's roulette decided at once); both checked.
TEST(SobolSampler, CoherentPairsAreOnePerEightByEightBlockAndStillStratified) {
    ensureGlContext();
    Program program = probeProgram(1);
    expectEveryPrefixStratified(program, true);

    const int size = 32;
    program.use();
    program.set("uMode", 3);
    program.set("uSeed", 5u);
    for (uint32_t sample : {0u, 1u, 6u}) {
        program.set("uSample", sample);
        std::vector<glm::vec4> points = drawProbe(program, size, size)[0];
        std::vector<glm::vec2> blockPoints;
        int neighboursDiffer = 0, neighbourPairs = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                glm::vec4 p = points[size_t(y * size + x)];
                glm::vec4 corner = points[size_t((y & ~7) * size + (x & ~7))];
                ASSERT_EQ(glm::vec2(p), glm::vec2(corner))
                    << "sample " << sample << ", pixel " << x << "," << y;
                if (x % 8 == 0 && y % 8 == 0) blockPoints.push_back(glm::vec2(p));
                if (x + 1 < size) {
                    ++neighbourPairs;
                    neighboursDiffer += glm::vec2(p.z, p.w) != glm::vec2(points[size_t(y * size + x + 1)].z,
                                                                         points[size_t(y * size + x + 1)].w);
                }
            }
        for (size_t i = 0; i < blockPoints.size(); ++i)
            for (size_t j = 0; j < i; ++j)
                EXPECT_NE(blockPoints[i], blockPoints[j])
                    << "sample " << sample << ": blocks " << i << ", " << j;
        EXPECT_EQ(neighboursDiffer, neighbourPairs) << "sample " << sample << ": the next pair is shared too";
    }
}

// The scramble is a pure function of (seed, pixel, sample, pair): the same numbers twice, other numbers
// for another seed, another pixel or another pair, and no visible correlation between pairs (Burley's
// padding: each pair shuffles the samples with its own hash).
TEST(SobolSampler, ScramblesAreDeterministicAndDifferBySeedPixelAndPair) {
    ensureGlContext();
    Program program = probeProgram(1);
    const int n = 256;
    std::vector<glm::vec4> a = pixelSamples(program, 3, {9, 4}, n),
                           again = pixelSamples(program, 3, {9, 4}, n);
    std::vector<glm::vec4> otherSeed = pixelSamples(program, 4, {9, 4}, n),
                           otherPixel = pixelSamples(program, 3, {10, 4}, n);
    int sameSeed = 0, sameOtherSeed = 0, sameOtherPixel = 0;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int k = 0; k < n; ++k) {
        sameSeed += a[size_t(k)] == again[size_t(k)];
        sameOtherSeed += a[size_t(k)].x == otherSeed[size_t(k)].x;
        sameOtherPixel += a[size_t(k)].x == otherPixel[size_t(k)].x;
        double x = a[size_t(k)].x, y = a[size_t(k)].z;  // the first coordinates of pairs 0 and 1
        sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
    }
    EXPECT_EQ(sameSeed, n);
    EXPECT_LT(sameOtherSeed, 3);
    EXPECT_LT(sameOtherPixel, 3);
    double r =
        (sxy / n - sx / n * sy / n) / std::sqrt((sxx / n - sx * sx / n / n) * (syy / n - sy * sy / n / n));
    EXPECT_LT(std::abs(r), 0.25) << "pairs 0 and 1 correlated (independent: standard deviation 1/16)";
}

// Blue noise (rng.glsl): at every sample count, a pixel's points fill every interval of 1 / spp of
// each coordinate, and the pixels of an aligned 2x2 or 4x4 block together fill every interval of
// 1 / (spp x pixels): neighbours sample different parts of each dimension. Checked on the first
// coordinate of pairs 0 to 7 over a 32x32 corner, for 1, 4 and 16 samples. Catches a scramble that
// differs by pixel (white noise), a shift applied after the scramble, or a Z-order that is not.
TEST(SobolSampler, NeighbouringPixelsFillFinerIntervals) {
    ensureGlContext();
    Program program = probeProgram(1);
    const uint32_t seed = 5;
    std::vector<std::vector<uint32_t>> samples;  // samples[k][(y * kSize + x) * kNumbers + pair]
    for (uint32_t k = 0; k < 16; ++k) samples.push_back(streams(program, seed, k));
    for (int spp : {1, 4, 16})
        for (int b : {2, 4})
            for (int pair = 0; pair < kNumbers; ++pair)
                for (int by = 0; by < 32; by += b)
                    for (int bx = 0; bx < 32; bx += b) {
                        const int points = spp * b * b;
                        std::vector<int> cells(size_t(points), 0);
                        for (int k = 0; k < spp; ++k)
                            for (int y = by; y < by + b; ++y)
                                for (int x = bx; x < bx + b; ++x) {
                                    uint32_t n =
                                        samples[size_t(k)][size_t(y * kSize + x) * kNumbers + size_t(pair)];
                                    ++cells[size_t((uint64_t(n) * uint64_t(points)) >> 24)];
                                }
                        for (int c : cells)
                            ASSERT_EQ(c, 1) << spp << " spp, block " << b << "x" << b << " at " << bx << ","
                                            << by << ", pair " << pair;
                    }
}

}  // namespace
}  // namespace fp::test
