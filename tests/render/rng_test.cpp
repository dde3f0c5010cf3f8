// The random streams of glsl/common/rng.glsl, read back through a probe pass: no two (pixel, sample)
// streams may share numbers. A generator whose streams are windows of one 32-bit sequence fails this
// once the windows of all the streams add up to a sizeable part of 2^32 (a 512x512 render at a few
// hundred samples per pixel): two streams then run through the same numbers, shifted, and the pixels
// or samples that own them are correlated instead of independent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
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

// The first kNumbers numbers of every stream of sample `sample`, as the 24-bit integers rand() scales.
std::vector<uint32_t> streams(Program& program, uint32_t seed, uint32_t sample) {
    GLuint textures[2], framebuffer, vertexArray;
    glGenTextures(2, textures);
    glGenFramebuffers(1, &framebuffer);
    glGenVertexArrays(1, &vertexArray);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    for (int i = 0; i < 2; ++i) {
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kSize, kSize, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, textures[i],
                               0);
    }
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    program.use();
    program.set("uSeed", seed);
    program.set("uSample", sample);
    glViewport(0, 0, kSize, kSize);
    glDisable(GL_BLEND);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<glm::vec4> halves[2];
    for (int i = 0; i < 2; ++i) {
        halves[i].resize(size_t(kSize) * kSize);
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, halves[i].data());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(2, textures);
    if (glGetError() != GL_NO_ERROR) throw Error("random-stream probe: GL error");
    std::vector<uint32_t> numbers;
    numbers.reserve(halves[0].size() * kNumbers);
    for (size_t p = 0; p < halves[0].size(); ++p)
        for (int i = 0; i < kNumbers; ++i)
            numbers.push_back(uint32_t(halves[i / 4][p][i % 4] * 16777216.0f));  // exact: 24-bit values
    return numbers;
}

TEST(RandomStreams, NoTwoStreamsShareNumbers) {
    ensureGlContext();
    // FP_RNG_TEST_SHADERS may name a glsl/ directory to test instead of the built-in copy (to check
    // that this test fails on a generator with overlapping streams).
    const char* directory = std::getenv("FP_RNG_TEST_SHADERS");
    Program program(ShaderLibrary(directory ? directory : ""), "passes/fullscreen.vert.glsl",
                    "tests/rng_probe.frag.glsl", {});
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

}  // namespace
}  // namespace fp::test
