#pragma once
// A roofline per GPU (Williams, Waterman and Patterson 2009, "Roofline: an insightful visual performance
// model for multicore architectures", CACM): the paths per second that each of its limits allows, FP32
// arithmetic, DRAM bandwidth and (with ray-tracing hardware) its ray rate, for the average path the cost
// view measured; the least of them binds.
#include <limits>
#include <optional>
#include <string>

#include "settings/render_settings.h"
#include "study/flop_model.h"
#include "study/gpus.h"

namespace fp::study {

// Bytes the shader reads, from glsl/common/scene_data.glsl's fetches of the texels of pack/layout.h:
// - a node visited (intersect.glsl traverse): its four RGBA32UI texels, 64 (pack/quantised_node.h: grid
//   origin and scale exponents, x and y planes, z planes, child links);
// - a triangle tested (intersectLeaves): fetchTriangle's three RGBA32F texels, 48 ((v0, material),
//   (e1, light pmf), (e2, flags));
// - a surface shaded (surface.glsl surfaceAt): the hit triangle again (48), its three vertex normals
//   (fetchShadingNormal, 3 x 16 = 48) and the material's first four texels (bsdf.glsl fetchMaterial,
//   64): 160. Untextured, not metallic-roughness, no alpha: maps, texture coordinates and the extra
//   material texels read more, so this is a lower bound for such scenes;
// - nee and bdpt, per surface, the light sample (lights.glsl sampleEmitterPoint and emitterRadiance):
//   pickLight's binary search reads ceil(log2 L) cdf texels of the L light entries, then the picked
//   entry, its triangle (48), the entry below it and the emission texel (16 each): 96 + 16 ceil(log2 L).
//   lightPdf's re-read of an emitter hit by a BSDF ray is left out (it happens on few vertices).
// Every read is counted as DRAM traffic, as if no cache held anything: the memory limit below is a
// lower bound on what the bandwidth allows. Scenes smaller than a GPU's L2 cache (the Cornell box's
// buffers are a few kilobytes) are read from the caches after the first frame, so for them the memory
// limit says what the bandwidth would allow the same traversal on a large scene.
constexpr double kBytesPerNode = 64.0;
constexpr double kBytesPerTriangleTest = 48.0;
constexpr double kBytesPerSurface = 160.0;
double lightSampleBytes(int lightEntries);
double bytesPerSurface(Integrator integrator, int lightEntries);
// nodes x 64 + triangles x 48: what ray-tracing hardware fetches too (in its own format; ours stands in).
double traversalBytesPerPath(const PathCounts& counts);
double bytesPerPath(const PathCounts& counts, Integrator integrator, int lightEntries);

// INT32 instructions, counted in the GLSL as flop_model.h counts FLOPs (one per integer add, multiply,
// multiply-add, shift, and, or, xor, compare, select and int/float conversion; an estimate of what the
// compiler emits, which may fold some):
// - a node visited: the scale exponents (3 shifts, 3 ands, 3 shifts) 9; the six planes' bytes
//   (planeSteps: 4 shifts, 4 ands, 4 conversions each) 72 and their six selects by direction 6; the
//   hit mask (link != 0 and the and) 8; the texel addresses and the counter 5; the leaf mask 8; the leaf
//   counts (shift, and, add, two multiplies per child) 20 and their test 4; the leaf ranges' first
//   triangles 4; the cull mask 4; the sorting network's link swaps (5 x 2 selects) 10; the stack pushes
//   (3 x select, add, address) 9 and pop 2: 161;
// - a triangle tested: the loop's range selects (3 compares, 3 selects, 1 add), the stray-index guard
//   (2), the loop counter (2), the three texel addresses (3) and the material's conversion (1): 15;
// - a ray: the traversal's set-up and the path counters: 8;
// - a surface: surfaceAt's texel addresses and conversions, 13, plus 127 per two-dimensional random
//   sample of the default Sobol sampler (rng.glsl rand2: pcg4d 20, two Laine-Karras permutations with
//   bit reversal 20, the pixel's mask and select 2, subsetParities 28 and sobolSecondReversed 28 on both
//   indices, the two xors 2, two more permutations 18, reversals 2, shifts 2 and conversions 2, its
//   stream test 2 and counter 1; rand() draws a whole pair): naive 1 pair (the hemisphere direction),
//   bsdf 2 (bsdfSample's rand2 and rand), nee and bdpt 4 (the environment test, the light point, the
//   BSDF sample's two), plus for nee and bdpt pickLight's binary search, 5 per step, and 4 addresses.
//   Russian roulette's sample (after the third bounce only) is left out.
constexpr double kIntPerNode = 161.0;
constexpr double kIntPerTriangleTest = 15.0;
constexpr double kIntPerRay = 8.0;
constexpr double kIntPerSurface = 13.0;
constexpr double kIntPerSamplePair = 127.0;
double intPerSurface(Integrator integrator, int lightEntries);
// Every INT32 instruction of a path, and those left on the SMs when RT cores traverse (the surfaces').
double intPerPath(const PathCounts& counts, Integrator integrator, int lightEntries);
double shadingIntPerPath(const PathCounts& counts, Integrator integrator, int lightEntries);
// The FLOPs left on the SMs when RT cores traverse: the camera ray and the surfaces.
double shadingFlopsPerPath(const PathCounts& counts, Integrator integrator);

// What one scene's average path costs, as the cost view measured it.
struct PathWork {
    PathCounts counts;
    Integrator integrator = Integrator::Nee;
    int lightEntries = 0;  // of the light-selection cdf (pack/layout.h): emitter triangles + punctual lights
};

constexpr double kUnlimited = std::numeric_limits<double>::infinity();

enum class Limit { Compute, Memory, Rays };
const char* limitName(Limit l);

// Paths per second each limit allows on one GPU.
// - compute: peak x fp32Fraction(lanes, INT32 per FP32 instruction) x efficiency / FLOPs per path; the
//   FP32 instructions are taken as the FLOPs (an FMA's two FLOPs are one instruction, so this
//   understates the integer share a little). On GPUs with RT cores only the shading's FLOPs and
//   integer work stay on the SMs: the RT cores traverse and test triangles.
// - memory: bandwidth / bytesPerPath.
// - rays: giga rays per second / rays per path, for GPUs with RT cores (kUnlimited otherwise).
struct RooflineLimits {
    double compute = kUnlimited, memory = kUnlimited, rays = kUnlimited;
    double fp32Fraction = 1.0, intPerFp = 0.0;
    Limit binding() const;
    double bindingPathsPerSecond() const;
};
RooflineLimits rooflineLimits(const Gpu& gpu, const PathWork& work, double efficiency = 1.0);

// Paths per second for 1920x1080 at 60 frames per second at `spp` samples per pixel.
double requiredPathsPerSecond(double spp);

// The first GPU of a class whose binding limit reaches `required` paths per second, and the year a
// least-squares fit of log2(binding limit) against the year (within the class) reaches it.
struct ClassAnswer {
    std::optional<int> year;
    std::string gpu;
    double trendYear = 0.0;
};
ClassAnswer firstReaching(GpuClass gpuClass, double requiredPathsPerSecond, const PathWork& work,
                          double efficiency = 1.0);

}  // namespace fp::study
